// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkSyntheticFibersSource
 * @brief   Generates smooth random polylines ("fibers") with radius and scalar arrays.
 *
 * The demonstration, test and benchmark data set of SplineViz: NumberOfTubes
 * smooth random curves with NumberOfSegments line segments in total (the
 * segments are distributed over the tubes with varying lengths, summing to
 * exactly NumberOfSegments), kept inside a cube of edge BoxSize centred at the
 * origin. Each curve is a random walk of constant StepLength whose direction
 * turns smoothly (a random, slowly varying angular velocity bounded by
 * MaximumTurn radians per step) and is steered back when it approaches the
 * walls of the box.
 *
 * Output: one polyline cell per tube, with point arrays
 * - "Radius" (float): a smooth radius in [RadiusRange[0], RadiusRange[1]]
 *   (world units), varying along each tube;
 * - "Scalar" (float): a smooth scalar in [0, 1] (arc length of the tube
 *   modulated by a per-tube phase), for color mapping;
 * and the cell array "TubeId" (the index of the tube among all pieces).
 *
 * Presets reproduce the sizes of the data sets of Salm, "Interactive Rendering
 * of Spline Tubes" (Fig. 19): Fibers (241 tubes, 3,530 segments), Fibers2
 * (1,701 tubes, 114,489 segments), and a larger 1 M segment set; they also
 * set BoxSize (1, 3.1, 6.4) so that the tubes fill about 1.5% of the box,
 * the density of white-matter tracts in a brain.
 *
 * The output is deterministic for a given Seed, independent of the number of
 * threads, and honours piece requests: piece p of n generates a contiguous
 * range of whole tubes, so ParaView's parallel pipeline splits the work.
 * Progress is reported and abort honoured between batches of tubes; sizes
 * that could not fit in this machine's memory are refused with an error
 * before anything is allocated.
 */

#ifndef vtkSyntheticFibersSource_h
#define vtkSyntheticFibersSource_h

#include "SplineVizFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class SPLINEVIZFILTERS_EXPORT vtkSyntheticFibersSource : public vtkPolyDataAlgorithm
{
public:
  static vtkSyntheticFibersSource* New();
  vtkTypeMacro(vtkSyntheticFibersSource, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Data set sizes of the presets.
  enum Presets
  {
    CUSTOM = 0,
    FIBERS = 1,     ///< 241 tubes, 3,530 segments (Salm's "Fibers")
    FIBERS2 = 2,    ///< 1,701 tubes, 114,489 segments (Salm's "Fibers2")
    ONE_MILLION = 3 ///< 8,000 tubes, 1,000,000 segments
  };

  ///@{
  /**
   * Set NumberOfTubes, NumberOfSegments and BoxSize to those of a preset (see
   * Presets). CUSTOM leaves them unchanged. Changing either count by hand
   * makes the preset CUSTOM.
   */
  void SetPreset(int preset);
  vtkGetMacro(Preset, int);
  void SetPresetToFibers() { this->SetPreset(FIBERS); }
  void SetPresetToFibers2() { this->SetPreset(FIBERS2); }
  void SetPresetToOneMillion() { this->SetPreset(ONE_MILLION); }
  ///@}

  ///@{
  /**
   * Number of tubes (polylines). Default 241.
   */
  void SetNumberOfTubes(vtkIdType n);
  vtkGetMacro(NumberOfTubes, vtkIdType);
  ///@}

  ///@{
  /**
   * Total number of line segments over all tubes; must be at least
   * NumberOfTubes (every tube has at least one segment). Default 3530.
   */
  void SetNumberOfSegments(vtkIdType n);
  vtkGetMacro(NumberOfSegments, vtkIdType);
  ///@}

  ///@{
  /**
   * Edge length of the cube (centred at the origin) the tubes stay in. Default 1.
   */
  vtkSetClampMacro(BoxSize, double, 1e-6, VTK_DOUBLE_MAX);
  vtkGetMacro(BoxSize, double);
  ///@}

  ///@{
  /**
   * Distance between successive points of a tube. Default 0.02.
   */
  vtkSetClampMacro(StepLength, double, 1e-9, VTK_DOUBLE_MAX);
  vtkGetMacro(StepLength, double);
  ///@}

  ///@{
  /**
   * Maximal turning angle between successive segments, in radians. Default 0.35.
   */
  vtkSetClampMacro(MaximumTurn, double, 0.0, 3.0);
  vtkGetMacro(MaximumTurn, double);
  ///@}

  ///@{
  /**
   * Range of the "Radius" point array, in world units. Default [0.004, 0.012].
   */
  vtkSetVector2Macro(RadiusRange, double);
  vtkGetVector2Macro(RadiusRange, double);
  ///@}

  ///@{
  /**
   * Seed of the random generator. Default 1.
   */
  vtkSetMacro(Seed, unsigned int);
  vtkGetMacro(Seed, unsigned int);
  ///@}

protected:
  vtkSyntheticFibersSource();
  ~vtkSyntheticFibersSource() override = default;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Preset = FIBERS;
  vtkIdType NumberOfTubes = 241;
  vtkIdType NumberOfSegments = 3530;
  double BoxSize = 1.0;
  double StepLength = 0.02;
  double MaximumTurn = 0.35;
  double RadiusRange[2] = { 0.004, 0.012 };
  unsigned int Seed = 1;

private:
  vtkSyntheticFibersSource(const vtkSyntheticFibersSource&) = delete;
  void operator=(const vtkSyntheticFibersSource&) = delete;
};

#endif
