// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkSyntheticTractogramSource
 * @brief   Generates a synthetic whole-brain tractogram: bundles of smooth, densely
 * packed streamlines in a brain-sized volume, in millimetres.
 *
 * The benchmark and test data of the line renderers at tractography's real
 * sizes (10^4 to 10^7 streamlines). NumberOfBundles smooth centre lines run
 * through an ellipsoid of semi-axes BrainRadii (default 70 x 85 x 60 mm, a
 * human brain in RAS+ mm), steered back when they approach its surface. Each
 * streamline belongs to bundle (index mod NumberOfBundles), starts at a random
 * place along its bundle's centre line and follows it for a random number of
 * points in [MinimumPoints, MaximumPoints], StepLength apart (1 mm, as
 * MRtrix's and DIPY's tracking write them), at an offset from the centre line
 * that wanders slowly inside the bundle's radius (BundleRadiusRange): tight,
 * overlapping, crossing bundles, many streamlines behind every pixel, as in
 * the tractograms of whole-brain tracking.
 *
 * Output: one polyline per streamline, float points, point array "FA" (a
 * smooth value in [0.2, 0.9]) as active scalars, cell arrays "StreamlineId"
 * and "BundleId". Deterministic for a Seed (each streamline from its own
 * random sequence, independent of threads and pieces); piece requests give a
 * contiguous range of streamlines, so ParaView's parallel pipeline splits the
 * work. Progress and abort between batches; sizes that could not fit in this
 * machine's memory are refused before anything is allocated.
 */
#ifndef vtkSyntheticTractogramSource_h
#define vtkSyntheticTractogramSource_h

#include "SplineVizFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class SPLINEVIZFILTERS_EXPORT vtkSyntheticTractogramSource : public vtkPolyDataAlgorithm
{
public:
  static vtkSyntheticTractogramSource* New();
  vtkTypeMacro(vtkSyntheticTractogramSource, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Number of streamlines. Default 10,000.
  vtkSetClampMacro(NumberOfStreamlines, vtkIdType, 0, VTK_ID_MAX);
  vtkGetMacro(NumberOfStreamlines, vtkIdType);
  ///@}

  ///@{
  /// Number of bundles. Default 40.
  vtkSetClampMacro(NumberOfBundles, int, 1, 100000);
  vtkGetMacro(NumberOfBundles, int);
  ///@}

  ///@{
  /// Points per streamline: uniformly random in [MinimumPoints, MaximumPoints]. Default 50, 200.
  vtkSetClampMacro(MinimumPoints, int, 2, 100000);
  vtkGetMacro(MinimumPoints, int);
  vtkSetClampMacro(MaximumPoints, int, 2, 100000);
  vtkGetMacro(MaximumPoints, int);
  ///@}

  ///@{
  /// Distance between successive points, mm. Default 1.
  vtkSetClampMacro(StepLength, double, 1e-6, VTK_DOUBLE_MAX);
  vtkGetMacro(StepLength, double);
  ///@}

  ///@{
  /// Semi-axes (x, y, z) of the ellipsoid the bundles stay in, mm. Default 70, 85, 60.
  vtkSetVector3Macro(BrainRadii, double);
  vtkGetVector3Macro(BrainRadii, double);
  ///@}

  ///@{
  /// Range of the bundles' radii, mm. Default [2, 8].
  vtkSetVector2Macro(BundleRadiusRange, double);
  vtkGetVector2Macro(BundleRadiusRange, double);
  ///@}

  ///@{
  /// Seed of the random sequences. Default 1.
  vtkSetMacro(Seed, unsigned int);
  vtkGetMacro(Seed, unsigned int);
  ///@}

protected:
  vtkSyntheticTractogramSource();
  ~vtkSyntheticTractogramSource() override = default;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  vtkIdType NumberOfStreamlines = 10000;
  int NumberOfBundles = 40;
  int MinimumPoints = 50;
  int MaximumPoints = 200;
  double StepLength = 1.0;
  double BrainRadii[3] = { 70.0, 85.0, 60.0 };
  double BundleRadiusRange[2] = { 2.0, 8.0 };
  unsigned int Seed = 1;

private:
  vtkSyntheticTractogramSource(const vtkSyntheticTractogramSource&) = delete;
  void operator=(const vtkSyntheticTractogramSource&) = delete;
};

#endif
