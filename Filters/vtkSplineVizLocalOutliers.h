// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkSplineVizLocalOutliers
 * @brief   Finds data values that disagree with their neighbours: spikes in scattered or mesh
 * data that a fit should not chase.
 *
 * Plain C++ (not a vtkObject), used by vtkLRSplineFitter (RemoveOutliers). A
 * fit refined until every data point is within a tolerance refines down to
 * its finest level around a single wrong value (a sensor dropout, a diverged
 * cell, a unit mix-up). A real feature is shared by neighbouring points; a
 * wrong value is not. So, for every point p:
 *
 * 1. its K nearest other data points (K = NumberOfNeighbors; a uniform grid
 *    searched ring by ring);
 * 2. a linear model of their values by least squares, refitted up to three
 *    times without the neighbours farther from it than 5 max(their spread,
 *    Tolerance) (spread: 1.4826 median |residual|);
 * 3. D_p = how far that model misses p's value;
 * 4. p is an outlier when D_p > Threshold max(s_p, m_p, Tolerance), with s_p
 *    the spread of p's neighbours about the model and m_p = 1.4826 median of
 *    their own D_q (taken from models fitted without p when it matters).
 *
 * s_p covers extrema and sharp features sampled by several points, m_p the
 * data's boundary, where every neighbourhood is one-sided. Vector values are
 * tested as vectors (the length of the residual). A feature carried by one
 * data point alone cannot be told from a wrong value and is reported as an
 * outlier. Runs on all cores (vtkSMPTools), with progress and abort through
 * the calling algorithm. Why both scales: docs/lr-fitting.md, "Outliers".
 */

#ifndef vtkSplineVizLocalOutliers_h
#define vtkSplineVizLocalOutliers_h

#include "SplineVizFiltersModule.h" // for export macro
#include "vtkType.h"

#include <vector>

class vtkAlgorithm;

class SPLINEVIZFILTERS_EXPORT vtkSplineVizLocalOutliers
{
public:
  /// Neighbours a value is compared with (at least 8).
  int NumberOfNeighbors = 16;
  /// A value is an outlier beyond this many times max(local spread, Tolerance).
  double Threshold = 5.0;
  /// The smallest deviation that can make an outlier, in the values' units (> 0).
  double Tolerance = 0.0;

  /**
   * Test every point: `positions` (3 per point), `values` (`dim` per point).
   * `deviation` gets D_p over the scale of step 4 per point, `outlier` 1
   * for the outliers. Progress from `from` to `to` on `algorithm` (may be
   * null). Returns false when aborted or with fewer than NumberOfNeighbors + 1
   * points (nothing is then marked).
   */
  bool Find(const std::vector<double>& positions, const std::vector<double>& values, int dim,
    std::vector<double>& deviation, std::vector<unsigned char>& outlier,
    vtkAlgorithm* algorithm = nullptr, double from = 0.0, double to = 1.0) const;

  /**
   * The model of step 2 for one point: neighbours `ids` (their positions
   * and values in the arrays above; on return, those kept), centre x_p.
   * Writes a (dim values) and returns the spread of all of `ids` about it.
   */
  double FitNeighbourhood(const std::vector<double>& positions, const std::vector<double>& values,
    int dim, const double centre[3], std::vector<vtkIdType>& ids, double* a) const;
};

#endif
