// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLRSplineBezierVolume.h"
#include "vtkSplineVizError.h"

#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkHigherOrderHexahedron.h"
#include "vtkHigherOrderQuadrilateral.h"
#include "vtkIdList.h"
#include "vtkLRSplineArrayNames.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSMPTools.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

using vtkSplineVizError::Fail;

//------------------------------------------------------------------------------
template <typename Real>
void vtkLRSplineBezierVolume::Bernstein(int n, Real s, Real* b, Real* d)
{
  const Real t = Real(1) - s;
  // Degree n-1 first (needed for the derivative), then raise to degree n.
  b[0] = Real(1);
  for (int k = 1; k < n; ++k)
  {
    Real saved = Real(0);
    for (int i = 0; i < k; ++i)
    {
      const Real tmp = b[i];
      b[i] = saved + t * tmp;
      saved = s * tmp;
    }
    b[k] = saved;
  }
  if (n == 0)
  {
    if (d)
    {
      d[0] = Real(0);
    }
    return;
  }
  if (d)
  {
    const Real rn = static_cast<Real>(n);
    d[0] = -rn * b[0];
    for (int i = 1; i < n; ++i)
    {
      d[i] = rn * (b[i - 1] - b[i]);
    }
    d[n] = rn * b[n - 1];
  }
  Real saved = Real(0);
  for (int i = 0; i < n; ++i)
  {
    const Real tmp = b[i];
    b[i] = saved + t * tmp;
    saved = s * tmp;
  }
  b[n] = saved;
}

namespace
{
constexpr int MaxComponents = 64;

// Value and local derivatives of one Bezier block: contraction along u, then v,
// then w. Sizes given as template arguments (> 0) are known at compile time
// (the common cases: fully unrolled); 0: the run-time ones (deg, ncDynamic;
// Cap: the largest number of components). Grad: 1 with the derivatives, 0
// without, -1 with them when dlocal is not null.
template <typename Real, int Cap, int NC, int NU, int NV, int NW, int Grad>
inline void ContractBlock(
  const Real* coeffs, const int deg[3], int ncDynamic, const Real s[3], Real* value, Real* dlocal)
{
  const int nc = NC > 0 ? NC : ncDynamic;
  const int nu = NU > 0 ? NU : deg[0] + 1;
  const int nv = NV > 0 ? NV : deg[1] + 1;
  const int nw = NW > 0 ? NW : deg[2] + 1;
  const bool grad = Grad >= 0 ? Grad == 1 : dlocal != nullptr;
  constexpr int M = NU > 0 && NV > 0 && NW > 0 ? std::max(NU, std::max(NV, NW))
                                               : vtkLRSplineBezierVolume::MaximumDegree + 1;
  Real bu[M], du[M], bv[M], dv[M], bw[M], dw[M];
  vtkLRSplineBezierVolume::Bernstein<Real>(nu - 1, s[0], bu, grad ? du : nullptr);
  vtkLRSplineBezierVolume::Bernstein<Real>(nv - 1, s[1], bv, grad ? dv : nullptr);
  vtkLRSplineBezierVolume::Bernstein<Real>(nw - 1, s[2], bw, grad ? dw : nullptr);

  Real val[Cap], gu[Cap], gv[Cap], gw[Cap];
  for (int c = 0; c < nc; ++c)
  {
    val[c] = gu[c] = gv[c] = gw[c] = Real(0);
  }
  for (int k = 0; k < nw; ++k)
  {
    Real A[Cap], Au[Cap], Av[Cap];
    for (int c = 0; c < nc; ++c)
    {
      A[c] = Au[c] = Av[c] = Real(0);
    }
    for (int j = 0; j < nv; ++j)
    {
      const Real* row = coeffs + static_cast<std::size_t>((k * nv + j) * nu) * nc;
      Real a[Cap], au[Cap];
      for (int c = 0; c < nc; ++c)
      {
        a[c] = au[c] = Real(0);
      }
      for (int i = 0; i < nu; ++i)
      {
        const Real* cf = row + i * nc;
        for (int c = 0; c < nc; ++c)
        {
          a[c] += cf[c] * bu[i];
          if (grad)
          {
            au[c] += cf[c] * du[i];
          }
        }
      }
      for (int c = 0; c < nc; ++c)
      {
        A[c] += a[c] * bv[j];
        if (grad)
        {
          Au[c] += au[c] * bv[j];
          Av[c] += a[c] * dv[j];
        }
      }
    }
    for (int c = 0; c < nc; ++c)
    {
      val[c] += A[c] * bw[k];
      if (grad)
      {
        gu[c] += Au[c] * bw[k];
        gv[c] += Av[c] * bw[k];
        gw[c] += A[c] * dw[k];
      }
    }
  }
  for (int c = 0; c < nc; ++c)
  {
    value[c] = val[c];
    if (grad)
    {
      dlocal[3 * c + 0] = gu[c];
      dlocal[3 * c + 1] = gv[c];
      dlocal[3 * c + 2] = gw[c];
    }
  }
}

// Any degrees; NC > 0 fixes the number of components at compile time.
template <typename Real, int NC>
void EvaluateBlock(
  const Real* coeffs, const int deg[3], int ncDynamic, const Real s[3], Real* value, Real* dlocal)
{
  ContractBlock<Real, (NC > 0 ? NC : MaxComponents), NC, 0, 0, 0, -1>(
    coeffs, deg, ncDynamic, s, value, dlocal);
}

// The common cases with compile-time degrees and components: fully unrolled.
template <typename Real, int NC, int DU, int DV, int DW, bool Grad>
inline void EvaluateFixed(const Real* coeffs, const Real s[3], Real* value, Real* dlocal)
{
  ContractBlock<Real, NC, NC, DU + 1, DV + 1, DW + 1, Grad ? 1 : 0>(
    coeffs, nullptr, NC, s, value, dlocal);
}

template <typename Real, int NC, int D>
inline bool TryFixed(
  const Real* coeffs, const int deg[3], const Real s[3], Real* value, Real* dlocal)
{
  if (deg[0] != D || deg[1] != D || deg[2] != D)
  {
    return false;
  }
  if (dlocal)
  {
    EvaluateFixed<Real, NC, D, D, D, true>(coeffs, s, value, dlocal);
  }
  else
  {
    EvaluateFixed<Real, NC, D, D, D, false>(coeffs, s, value, nullptr);
  }
  return true;
}

template <typename Real>
void Dispatch(
  const Real* coeffs, const int deg[3], int nc, const Real s[3], Real* value, Real* dlocal)
{
  switch (nc)
  {
    case 1:
      if (!TryFixed<Real, 1, 2>(coeffs, deg, s, value, dlocal) &&
        !TryFixed<Real, 1, 3>(coeffs, deg, s, value, dlocal))
      {
        EvaluateBlock<Real, 1>(coeffs, deg, nc, s, value, dlocal);
      }
      break;
    case 3:
      if (!TryFixed<Real, 3, 2>(coeffs, deg, s, value, dlocal) &&
        !TryFixed<Real, 3, 3>(coeffs, deg, s, value, dlocal) &&
        !TryFixed<Real, 3, 1>(coeffs, deg, s, value, dlocal))
      {
        EvaluateBlock<Real, 3>(coeffs, deg, nc, s, value, dlocal);
      }
      break;
    default:
      EvaluateBlock<Real, 0>(coeffs, deg, nc, s, value, dlocal);
      break;
  }
}
}

template SPLINEVIZCORE_EXPORT void vtkLRSplineBezierVolume::Bernstein<double>(
  int, double, double*, double*);
template SPLINEVIZCORE_EXPORT void vtkLRSplineBezierVolume::Bernstein<float>(
  int, float, float*, float*);

//------------------------------------------------------------------------------
void vtkLRSplineBezierVolume::GetDomain(double domain[6]) const
{
  for (int d = 0; d < 3; ++d)
  {
    domain[d] = std::numeric_limits<double>::infinity();
    domain[d + 3] = -std::numeric_limits<double>::infinity();
  }
  const vtkIdType n = this->GetNumberOfElements();
  for (vtkIdType e = 0; e < n; ++e)
  {
    const double* b = this->GetBox(e);
    for (int d = 0; d < 3; ++d)
    {
      domain[d] = std::min(domain[d], b[d]);
      domain[d + 3] = std::max(domain[d + 3], b[d + 3]);
    }
  }
}

//------------------------------------------------------------------------------
void vtkLRSplineBezierVolume::MakeFloatCoefficients()
{
  this->CoefficientsFloat.assign(this->Coefficients.begin(), this->Coefficients.end());
}

//------------------------------------------------------------------------------
void vtkLRSplineBezierVolume::ElevateToAtLeastLinear(int parametricDimension)
{
  const int pd = std::max(1, std::min(3, parametricDimension));
  bool linear = true;
  for (int d = 0; d < pd; ++d)
  {
    linear = linear && this->Degree[d] >= 1;
  }
  if (linear)
  {
    return;
  }
  const int nc = this->NumberOfComponents;
  const int old[3] = { this->Degree[0] + 1, this->Degree[1] + 1, this->Degree[2] + 1 };
  int neu[3];
  for (int d = 0; d < 3; ++d)
  {
    neu[d] = d < pd ? std::max(old[d], 2) : old[d];
  }
  const vtkIdType ne = this->GetNumberOfElements();
  const std::size_t oldPer = static_cast<std::size_t>(old[0] * old[1] * old[2] * nc);
  const std::size_t newPer = static_cast<std::size_t>(neu[0] * neu[1] * neu[2] * nc);
  std::vector<double> out(newPer * ne);
  for (vtkIdType e = 0; e < ne; ++e)
  {
    const double* src = this->Coefficients.data() + oldPer * e;
    double* dst = out.data() + newPer * e;
    for (int k = 0; k < neu[2]; ++k)
    {
      for (int j = 0; j < neu[1]; ++j)
      {
        for (int i = 0; i < neu[0]; ++i)
        {
          // A constant direction (degree 0) has one coefficient, repeated.
          const int si = old[0] == 1 ? 0 : i;
          const int sj = old[1] == 1 ? 0 : j;
          const int sk = old[2] == 1 ? 0 : k;
          const double* c = src + ((sk * old[1] + sj) * old[0] + si) * nc;
          std::copy(c, c + nc, dst + ((k * neu[1] + j) * neu[0] + i) * nc);
        }
      }
    }
  }
  this->Coefficients.swap(out);
  for (int d = 0; d < 3; ++d)
  {
    this->Degree[d] = neu[d] - 1;
  }
  if (!this->CoefficientsFloat.empty())
  {
    this->MakeFloatCoefficients();
  }
}

//------------------------------------------------------------------------------
bool vtkLRSplineBezierVolume::Dehomogenize(int weightComponent, std::string* error)
{
  const int nc = this->NumberOfComponents;
  if (weightComponent < 0 || weightComponent >= nc)
  {
    if (error)
    {
      *error = "the weight component " + std::to_string(weightComponent) + " does not exist";
    }
    return false;
  }
  const std::size_t n = this->Coefficients.size() / static_cast<std::size_t>(nc);
  for (std::size_t k = 0; k < n; ++k)
  {
    const double w = this->Coefficients[k * nc + weightComponent];
    if (!(w > 0) || !std::isfinite(w))
    {
      if (error)
      {
        std::ostringstream msg;
        msg << "element " << k / this->GetCoefficientsPerElement()
            << " has a Bezier weight that is not positive (" << w << ")";
        *error = msg.str();
      }
      return false;
    }
  }
  for (std::size_t k = 0; k < n; ++k)
  {
    double* c = this->Coefficients.data() + k * nc;
    const double w = c[weightComponent];
    for (int comp = 0; comp < nc; ++comp)
    {
      if (comp != weightComponent)
      {
        c[comp] /= w;
      }
    }
  }
  if (!this->CoefficientsFloat.empty())
  {
    this->MakeFloatCoefficients();
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkLRSplineBezierVolume::ElevateDegree(const int degree[3])
{
  for (int d = 0; d < 3; ++d)
  {
    if (degree[d] < this->Degree[d] || degree[d] > MaximumDegree)
    {
      return false;
    }
  }
  const int nc = this->NumberOfComponents;
  const vtkIdType ne = this->GetNumberOfElements();
  for (int d = 0; d < 3; ++d)
  {
    while (this->Degree[d] < degree[d])
    {
      // One degree up along direction d: n = Degree[d] -> n + 1.
      const int n = this->Degree[d];
      int old[3] = { this->Degree[0] + 1, this->Degree[1] + 1, this->Degree[2] + 1 };
      int neu[3] = { old[0], old[1], old[2] };
      neu[d] = old[d] + 1;
      const std::size_t oldPer = static_cast<std::size_t>(old[0]) * old[1] * old[2] * nc;
      const std::size_t newPer = static_cast<std::size_t>(neu[0]) * neu[1] * neu[2] * nc;
      std::vector<double> out(newPer * ne);
      vtkSMPTools::For(0, ne,
        [&](vtkIdType begin, vtkIdType end)
        {
          for (vtkIdType e = begin; e < end; ++e)
          {
            const double* src = this->Coefficients.data() + oldPer * e;
            double* dst = out.data() + newPer * e;
            for (int k = 0; k < neu[2]; ++k)
            {
              for (int j = 0; j < neu[1]; ++j)
              {
                for (int i = 0; i < neu[0]; ++i)
                {
                  const int idx[3] = { i, j, k };
                  const int m = idx[d]; // 0 .. n + 1
                  const double a = static_cast<double>(m) / (n + 1);
                  int lo[3] = { i, j, k }, hi[3] = { i, j, k };
                  lo[d] = m - 1;
                  hi[d] = m;
                  double* c = dst + ((k * neu[1] + j) * neu[0] + i) * nc;
                  for (int comp = 0; comp < nc; ++comp)
                  {
                    double v = 0.0;
                    if (m >= 1)
                    {
                      v += a * src[((lo[2] * old[1] + lo[1]) * old[0] + lo[0]) * nc + comp];
                    }
                    if (m <= n)
                    {
                      v += (1.0 - a) * src[((hi[2] * old[1] + hi[1]) * old[0] + hi[0]) * nc + comp];
                    }
                    c[comp] = v;
                  }
                }
              }
            }
          }
        });
      this->Coefficients.swap(out);
      ++this->Degree[d];
    }
  }
  if (!this->CoefficientsFloat.empty())
  {
    this->MakeFloatCoefficients();
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkLRSplineBezierVolume::EvaluateLocal(
  vtkIdType e, const double s[3], double* value, double* dlocal) const
{
  Dispatch<double>(
    this->GetElementCoefficients(e), this->Degree, this->NumberOfComponents, s, value, dlocal);
}

void vtkLRSplineBezierVolume::EvaluateLocal(
  vtkIdType e, const float s[3], float* value, float* dlocal) const
{
  const float* c = this->CoefficientsFloat.data() +
    e * this->GetCoefficientsPerElement() * this->NumberOfComponents;
  Dispatch<float>(c, this->Degree, this->NumberOfComponents, s, value, dlocal);
}

//------------------------------------------------------------------------------
bool vtkLRSplineBezierVolume::FromUnstructuredGrid(vtkUnstructuredGrid* grid, const char* arrayName,
  std::string* error, std::vector<vtkIdType>* cellIds, std::string* usedArrayName)
{
  if (!grid)
  {
    return Fail(error, "no grid");
  }
  vtkPointData* pd = grid->GetPointData();
  vtkDataArray* field = nullptr;
  if (arrayName && *arrayName)
  {
    field = pd->GetArray(arrayName);
    if (!field)
    {
      return Fail(
        error, std::string("the spline grid has no point-data array named \"") + arrayName + "\"");
    }
  }
  else
  {
    field = pd->GetVectors() ? pd->GetVectors() : pd->GetScalars();
    for (int a = 0; !field && a < pd->GetNumberOfArrays(); ++a)
    {
      // The geometry's own arrays are not a field to evaluate.
      vtkDataArray* candidate = pd->GetArray(a);
      const char* n = candidate ? candidate->GetName() : nullptr;
      if (candidate && candidate != pd->GetRationalWeights() &&
        !(n &&
          (std::string(n) == vtkLRSplineArrayNames::ParameterCoordinates ||
            std::string(n) == vtkLRSplineArrayNames::RationalWeights)))
      {
        field = candidate;
      }
    }
    if (!field)
    {
      return Fail(error, "the spline grid has no point-data array to evaluate");
    }
  }
  if (usedArrayName)
  {
    *usedArrayName = field->GetName() ? field->GetName() : "";
  }
  const int nc = field->GetNumberOfComponents();
  if (nc < 1 || nc > MaxComponents)
  {
    return Fail(error, "the field array has an unsupported number of components");
  }
  vtkCellData* cd = grid->GetCellData();
  vtkDataArray* degrees = cd->GetHigherOrderDegrees();
  if (!degrees)
  {
    degrees = cd->GetArray("HigherOrderDegrees");
  }
  vtkDataArray* boxes = cd->GetArray(vtkLRSplineArrayNames::ParameterBox);
  if (boxes && boxes->GetNumberOfComponents() != 6)
  {
    boxes = nullptr;
  }

  this->NumberOfComponents = nc;
  this->Boxes.clear();
  this->Coefficients.clear();
  this->CoefficientsFloat.clear();
  if (cellIds)
  {
    cellIds->clear();
  }
  const vtkIdType numCells = grid->GetNumberOfCells();
  const int cellType = numCells > 0 ? grid->GetCellType(0) : VTK_BEZIER_HEXAHEDRON;
  const int pdim = cellType == VTK_BEZIER_QUADRILATERAL ? 2 : 3;
  this->ParametricDimension = pdim;
  bool haveDegree = false;
  vtkNew<vtkIdList> pts;
  for (vtkIdType cell = 0; cell < numCells; ++cell)
  {
    if (grid->GetCellType(cell) != cellType ||
      (cellType != VTK_BEZIER_HEXAHEDRON && cellType != VTK_BEZIER_QUADRILATERAL))
    {
      std::ostringstream msg;
      msg << "cell " << cell << " is not a VTK_BEZIER_HEXAHEDRON (volume) or, in a grid of them, a "
          << "VTK_BEZIER_QUADRILATERAL (surface)";
      return Fail(error, msg.str());
    }
    grid->GetCellPoints(cell, pts);
    int deg[3] = { 0, 0, 0 };
    if (degrees && degrees->GetNumberOfComponents() >= pdim)
    {
      for (int d = 0; d < pdim; ++d)
      {
        deg[d] = static_cast<int>(degrees->GetComponent(cell, d));
      }
    }
    else
    {
      // Like VTK: an isotropic degree from the number of points.
      const double count = static_cast<double>(pts->GetNumberOfIds());
      const int n = static_cast<int>(std::lround(pdim == 2 ? std::sqrt(count) : std::cbrt(count)));
      for (int d = 0; d < pdim; ++d)
      {
        deg[d] = n - 1;
      }
    }
    for (int d = 0; d < pdim; ++d)
    {
      if (deg[d] < 1 || deg[d] > MaximumDegree)
      {
        return Fail(error, "unsupported Bezier degree in the spline grid");
      }
    }
    if (!haveDegree)
    {
      std::copy(deg, deg + 3, this->Degree);
      haveDegree = true;
    }
    else if (deg[0] != this->Degree[0] || deg[1] != this->Degree[1] || deg[2] != this->Degree[2])
    {
      return Fail(error, "the Bezier cells of one spline grid must all have the same degrees");
    }
    const int per = (deg[0] + 1) * (deg[1] + 1) * (deg[2] + 1);
    if (pts->GetNumberOfIds() != per)
    {
      return Fail(error, "a Bezier cell has a number of points that does not match its degrees");
    }
    double box[6];
    if (boxes)
    {
      boxes->GetTuple(cell, box);
    }
    else
    {
      for (int d = 0; d < 3; ++d)
      {
        box[d] = std::numeric_limits<double>::infinity();
        box[d + 3] = -std::numeric_limits<double>::infinity();
      }
      for (int corner = 0; corner < (pdim == 2 ? 4 : 8); ++corner)
      {
        double x[3];
        grid->GetPoint(pts->GetId(corner), x);
        for (int d = 0; d < 3; ++d)
        {
          box[d] = std::min(box[d], x[d]);
          box[d + 3] = std::max(box[d + 3], x[d]);
        }
      }
      if (pdim == 2)
      {
        box[2] = 0.0; // a surface's w
        box[5] = 1.0;
      }
    }
    for (int d = 0; d < 3; ++d)
    {
      if (!(box[d] < box[d + 3]) || !std::isfinite(box[d]) || !std::isfinite(box[d + 3]))
      {
        std::ostringstream msg;
        msg << "cell " << cell << " has an empty or invalid parameter box";
        return Fail(error, msg.str());
      }
    }
    this->Boxes.insert(this->Boxes.end(), box, box + 6);
    const std::size_t base = this->Coefficients.size();
    this->Coefficients.resize(base + static_cast<std::size_t>(per) * nc);
    double* dst = this->Coefficients.data() + base;
    for (int k = 0; k <= deg[2]; ++k)
    {
      for (int j = 0; j <= deg[1]; ++j)
      {
        for (int i = 0; i <= deg[0]; ++i)
        {
          const int local = pdim == 2 ? vtkHigherOrderQuadrilateral::PointIndexFromIJK(i, j, deg)
                                      : vtkHigherOrderHexahedron::PointIndexFromIJK(i, j, k, deg);
          const vtkIdType pid = pts->GetId(local);
          double* c = dst + ((k * (deg[1] + 1) + j) * (deg[0] + 1) + i) * nc;
          for (int comp = 0; comp < nc; ++comp)
          {
            c[comp] = field->GetComponent(pid, comp);
          }
        }
      }
    }
    if (cellIds)
    {
      cellIds->push_back(cell);
    }
  }
  return true;
}
