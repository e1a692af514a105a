// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkSplineVizLocalOutliers
 * @brief   Finds data values that disagree with their neighbours: spikes in scattered or mesh
 * data that a fit should not chase.
 *
 * Plain C++ (not a vtkObject), used by vtkLRSplineFitter (RemoveOutliers).
 * A fit refined until every data point is within a tolerance refines down
 * to its finest level around a single wrong value (a sensor dropout, a
 * diverged cell, a unit mix-up), and the spline then shows the spike. What
 * tells a wrong value from a sharp but real feature is that a feature is
 * shared by neighbouring points. So, for every point p:
 *
 * 1. its K nearest other data points (K = NumberOfNeighbors; a uniform grid
 *    of about two points per cell searched ring by ring);
 * 2. a linear model f(x) = a + b . (x - x_p) fitted to their values by least
 *    squares (offsets scaled by the neighbourhood's radius, a tiny ridge on b
 *    so that neighbours on a plane or a line leave it well posed);
 *    neighbours farther from it than 5 max(their spread, Tolerance)
 *    (spread: 1.4826 median |residual|, the normal-consistent median
 *    absolute deviation) are dropped and the model fitted again, up to three
 *    times, so that wrong neighbours do not bend it;
 * 3. D_p = |f_p - a|, how far the model of its neighbours misses p;
 * 4. p is an outlier when D_p > Threshold max(s_p, m_p, Tolerance), with s_p
 *    the spread of all p's neighbours about the final model of step 2 and m_p =
 *    1.4826 median of D_q over p's neighbours q; when D_p exceeds
 *    Threshold max(s_p, Tolerance), so that m_p decides, each D_q is taken
 *    from q's model fitted without p (a wrong p bends its neighbours' models
 *    and would otherwise raise its own scale).
 *
 * The scale of step 4 says how well a linear model can predict values here.
 * At an extremum or a sharp feature sampled by several points the
 * neighbours scatter about their model (s_p); at the data's boundary, where
 * every neighbourhood is one-sided, the models miss the neighbours as much
 * as p (m_p); a lone spike is missed by far more than either. Each scale
 * alone took clean points for spikes: s_p at the boundary of ParaView's
 * clipped Wavelet, m_p at the peak of a narrow bump (a quadratic model did
 * no better). Vector values are tested as vectors (the length of the
 * residual vector). A feature carried by one data point alone cannot be
 * told from a wrong value and is reported as an outlier.
 *
 * Runs on all cores (vtkSMPTools), with progress and abort through the
 * calling algorithm.
 */

#ifndef vtkSplineVizLocalOutliers_h
#define vtkSplineVizLocalOutliers_h

#include "SplineVizModule.h" // for export macro
#include "vtkType.h"

#include <vector>

class vtkAlgorithm;

class SPLINEVIZ_EXPORT vtkSplineVizLocalOutliers
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
