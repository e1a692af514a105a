// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLRSplineBuilder
 * @brief   Generates LR-spline volumes by genuine local refinement (for tests, benchmarks and
 * demos).
 *
 * Plain C++ (not a vtkObject). Starts from a tensor-product B-spline volume
 * (open knot vectors) and refines it locally the LR-spline way (Dokken, Lyche
 * and Pettersen 2013; Fuchs et al. §3.1): a mesh rectangle is inserted, every
 * element it crosses is split, and every LR B-spline whose support the
 * (union of the) mesh rectangles at that value traverses is split by knot
 * insertion, B = a1 B1 + a2 B2, with the scaling weights gamma and the
 * coefficients updated so that the spline function does not change (a
 * function that appears twice is merged: gammas add, coefficients average
 * with the gamma weights). So a field that is exact before refinement (e.g.
 * a linear field from Greville coefficients) stays exact.
 *
 * RefineFunction() performs "structured mesh" refinement of one B-spline:
 * through every knot interval of its support, in every direction, a
 * rectangle at lo + ratio (hi - lo) spanning the support. A ratio other than
 * 1/2 (e.g. the golden section) gives non-dyadic, irrational knots; repeated
 * refinement near a point gives many refinement levels.
 *
 * GetPatch() gives the LR spline (vtkLRSplinePatch, which also writes the .lr
 * text format).
 */

#ifndef vtkLRSplineBuilder_h
#define vtkLRSplineBuilder_h

#include "SplineVizFiltersModule.h" // for export macro
#include "vtkLRSplinePatch.h"

#include <functional>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

class SPLINEVIZFILTERS_EXPORT vtkLRSplineBuilder
{
public:
  /**
   * A tensor-product spline of the given degrees whose distinct knots per
   * direction are `breaks` (end knots repeated degree + 1 times), with
   * `dimension` zero coefficients.
   */
  bool InitializeTensorProduct(
    const int degree[3], const std::vector<double> breaks[3], int dimension, std::string* error);

  /**
   * Coefficient of each basis function = f(its Greville point) (the average
   * of its interior knots per direction). Exact for linear f on a
   * tensor-product spline; a quasi-interpolant otherwise.
   */
  void SetCoefficientsFromGreville(const std::function<void(const double g[3], double* c)>& f);

  /**
   * Coefficient = f(interior knots u (degree values), v, w): with f the
   * blossom (polar form) of a polynomial of the spline's degree this
   * reproduces the polynomial exactly on a tensor-product spline.
   */
  void SetCoefficientsFromKnots(
    const std::function<void(const double* const interior[3], const int degree[3], double* c)>& f);

  /**
   * Insert a mesh rectangle (multiplicity 1): constant direction `dir` at
   * `value`, spanning `box` (6 values, lo xyz then hi xyz; the `dir` entries
   * are ignored) in the other two directions. Its edges must lie on existing
   * mesh planes (false otherwise).
   */
  bool InsertMeshRectangle(int dir, double value, const double box[6], std::string* error);

  /// Structured refinement of basis function i (see the class documentation).
  bool RefineFunction(vtkIdType i, double ratio, std::string* error);

  /// How RefineFunctions() places and limits the splits.
  struct RefineOptions
  {
    /// A knot interval [a, b] is split at a + Ratio (b - a) ...
    double Ratio = 0.5;
    /**
     * ... moved, where GridStep[d] > 0, to the nearest point of
     * GridOffset[d] + j GridStep[d] strictly inside the interval (no split if
     * there is none): e.g. the voxel centres or voxel faces of an image.
     */
    double GridStep[3] = { 0, 0, 0 };
    double GridOffset[3] = { 0, 0, 0 };
    /// No split that leaves a part shorter than this (per direction).
    double MinimumPart[3] = { 0, 0, 0 };
  };

  /**
   * Structured refinement of several basis functions at once (the adaptive
   * fitting of vtkLRSplineImageFitter): the rectangles RefineFunction() would
   * insert for each listed function (with the splits placed and limited by
   * `options`) are inserted together, the elements are split once and every
   * basis function the new rectangles traverse is split (the LR B-splines of
   * the resulting mesh, the same as inserting the rectangles one by one, but
   * the mesh is scanned once). A function none of whose intervals may be split
   * is left alone; dead or repeated ids are skipped. `inserted` (may be null)
   * receives the number of rectangles inserted. On failure the builder is
   * left in an undefined state.
   */
  bool RefineFunctions(const std::vector<vtkIdType>& ids, const RefineOptions& options,
    std::string* error, vtkIdType* inserted = nullptr);

  /// Where RefineFunctions() splits the knot interval [a, b] of direction d (false: it does not).
  static bool SplitValue(double a, double b, int d, const RefineOptions& options, double* z);

  /// Refine the basis function with the smallest support containing p.
  bool RefineAt(const double p[3], double ratio, std::string* error);

  /**
   * Replace the coefficients: Dimension values per basis function, in the
   * order of GetPatch() (which is called first, removing dead functions).
   */
  void SetCoefficients(const std::vector<double>& coefficients);

  /// The current LR spline (dead functions removed).
  const vtkLRSplinePatch& GetPatch();

  vtkIdType GetNumberOfElements() const
  {
    return static_cast<vtkIdType>(this->Patch.ElementBoxes.size() / 6);
  }
  vtkIdType GetNumberOfBasisFunctions() const { return this->NumberAlive; }

private:
  struct Rect2
  {
    double A0, A1, B0, B1; // extents in the two other directions (ascending order)
  };
  struct Rectangle
  {
    int Dir;
    double Value;
    double Box[6];
  };
  bool Covered(int dir, double value, const double support[6]) const;
  vtkIdType AddFunction(const double* knots, const double* coeff, double gamma);
  // Split the functions of `work` (and their children) until no mesh plane
  // traverses them; parentsFirst: largest supports first (see the .cxx).
  void Split(std::vector<vtkIdType>& work, bool parentsFirst);
  void Compact();
  std::string Key(const double* knots) const;
  // The rectangles of the structured refinement of function i.
  void FunctionRectangles(
    vtkIdType i, const RefineOptions& options, std::vector<Rectangle>& out) const;
  // Insert rectangles (multiplicity 1) together: planes, elements, functions.
  bool InsertRectangles(std::vector<Rectangle>& rects, bool parentsFirst, std::string* error);
  // Add r to the rectangles of its plane, merged with those it extends.
  static void AddToPlane(std::vector<Rect2>& plane, Rect2 r);

  vtkLRSplinePatch Patch;
  std::vector<char> Alive;
  vtkIdType NumberAlive = 0;
  std::unordered_map<std::string, vtkIdType> Index;
  std::map<double, std::vector<Rect2>> Planes[3];
};

#endif
// VTK-HeaderTest-Exclude: vtkLRSplineBuilder.h
