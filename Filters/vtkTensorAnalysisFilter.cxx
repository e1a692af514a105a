// SPDX-License-Identifier: BSD-3-Clause
#include "vtkTensorAnalysisFilter.h"

#include "vtkSplineVizProgress.h"
#include "vtkSplineVizTensorMath.h"

#include "vtkCellData.h"
#include "vtkDataSet.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"

#include <cmath>
#include <limits>
#include <vector>

vtkStandardNewMacro(vtkTensorAnalysisFilter);

namespace
{
namespace TM = vtkSplineVizTensorMath;

vtkSmartPointer<vtkDataArray> NewArray(bool dbl, const char* name, int comps, vtkIdType n)
{
  vtkSmartPointer<vtkDataArray> a;
  if (dbl)
  {
    a = vtkSmartPointer<vtkDoubleArray>::New();
  }
  else
  {
    a = vtkSmartPointer<vtkFloatArray>::New();
  }
  a->SetName(name);
  a->SetNumberOfComponents(comps);
  a->SetNumberOfTuples(n);
  return a;
}

template <typename T>
struct AnalysisWorker
{
  vtkDataArray* Tensors;
  int Layout;
  T* Values;
  T* Vectors[3];
  T* FA;
  T* MD;
  T* CL;
  T* CP;
  T* CS;
  T* Confidence;
  T* Shape; // Schultz-Kindlmann (u, v)
  // Counts per thread, kept across the batches of vtkSplineVizProgress::For
  // (so no Initialize() that would reset them per batch).
  vtkSMPThreadLocal<vtkIdType> Invalid{ 0 };

  void operator()(vtkIdType begin, vtkIdType end)
  {
    const T nan = std::numeric_limits<T>::quiet_NaN();
    vtkIdType& invalid = this->Invalid.Local();
    for (vtkIdType i = begin; i < end; ++i)
    {
      double t[6];
      double conf = 1.0;
      if (!TM::ReadSymmetric(this->Tensors, i, this->Layout, t, &conf))
      {
        ++invalid;
        for (int c = 0; c < 3; ++c)
        {
          this->Values[3 * i + c] = nan;
          for (int k = 0; k < 3; ++k)
          {
            if (this->Vectors[k])
            {
              this->Vectors[k][3 * i + c] = nan;
            }
          }
        }
        this->FA[i] = this->MD[i] = this->CL[i] = this->CP[i] = this->CS[i] = nan;
        this->Shape[2 * i] = this->Shape[2 * i + 1] = nan;
        if (this->Confidence)
        {
          // the confidence may still be meaningful, but the tuple is invalid
          this->Confidence[i] = nan;
        }
        continue;
      }
      double w[3], v[3][3];
      TM::EigenDecomposition(t, w, v);
      double cl, cp, cs;
      TM::WestinMetrics(w, cl, cp, cs);
      for (int c = 0; c < 3; ++c)
      {
        this->Values[3 * i + c] = static_cast<T>(w[c]);
        for (int k = 0; k < 3; ++k)
        {
          if (this->Vectors[k])
          {
            this->Vectors[k][3 * i + c] = static_cast<T>(v[k][c]);
          }
        }
      }
      this->FA[i] = static_cast<T>(TM::FractionalAnisotropy(w));
      this->MD[i] = static_cast<T>(TM::MeanDiffusivity(w));
      this->CL[i] = static_cast<T>(cl);
      this->CP[i] = static_cast<T>(cp);
      this->CS[i] = static_cast<T>(cs);
      double uv[2];
      TM::SchultzKindlmannSquare(w, false, uv);
      this->Shape[2 * i] = static_cast<T>(uv[0]);
      this->Shape[2 * i + 1] = static_cast<T>(uv[1]);
      if (this->Confidence)
      {
        this->Confidence[i] = static_cast<T>(conf);
      }
    }
  }
};

template <typename T>
T* Ptr(vtkDataArray* a)
{
  return a ? static_cast<T*>(a->GetVoidPointer(0)) : nullptr;
}

template <typename T>
vtkIdType Run(
  vtkDataArray* tensors, int layout, const std::vector<vtkDataArray*>& out, vtkAlgorithm* progress)
{
  AnalysisWorker<T> worker;
  worker.Tensors = tensors;
  worker.Layout = layout;
  worker.Values = Ptr<T>(out[0]);
  for (int k = 0; k < 3; ++k)
  {
    worker.Vectors[k] = Ptr<T>(out[1 + k]);
  }
  worker.FA = Ptr<T>(out[4]);
  worker.MD = Ptr<T>(out[5]);
  worker.CL = Ptr<T>(out[6]);
  worker.CP = Ptr<T>(out[7]);
  worker.CS = Ptr<T>(out[8]);
  worker.Confidence = Ptr<T>(out[9]);
  worker.Shape = Ptr<T>(out[10]);
  if (!vtkSplineVizProgress::For(progress, 0, tensors->GetNumberOfTuples(), 0, 8192,
        [&worker](vtkIdType begin, vtkIdType end) { worker(begin, end); }))
  {
    return -1; // aborted
  }
  vtkIdType invalid = 0;
  for (vtkIdType n : worker.Invalid)
  {
    invalid += n;
  }
  return invalid;
}
}

//------------------------------------------------------------------------------
vtkTensorAnalysisFilter::vtkTensorAnalysisFilter()
{
  // Default: the active point tensors.
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::TENSORS);
}

//------------------------------------------------------------------------------
int vtkTensorAnalysisFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkDataSet* input = vtkDataSet::GetData(inputVector[0], 0);
  vtkDataSet* output = vtkDataSet::GetData(outputVector, 0);
  if (!input || !output)
  {
    vtkErrorMacro("Input and output must be vtkDataSet.");
    return 0;
  }
  output->ShallowCopy(input);
  this->NumberOfInvalidTensors = 0;

  int association = vtkDataObject::FIELD_ASSOCIATION_POINTS;
  vtkDataArray* tensors = this->GetInputArrayToProcess(0, inputVector, association);
  if (!tensors)
  {
    if (input->GetNumberOfPoints() == 0 && input->GetNumberOfCells() == 0)
    {
      return 1; // an empty block: nothing to do
    }
    vtkErrorMacro("No tensor array: select a point or cell array with 6, 7 or 9 components "
                  "(SetInputArrayToProcess), or set active point tensors.");
    return 0;
  }
  const int comps = tensors->GetNumberOfComponents();
  const int layout = TM::ResolveLayout(this->TensorLayout, comps);
  if (layout < 0)
  {
    vtkErrorMacro("Tensor array '" << (tensors->GetName() ? tensors->GetName() : "(unnamed)")
                                   << "' has " << comps
                                   << " components, which does not fit the tensor layout '"
                                   << TM::GetLayoutName(this->TensorLayout)
                                   << "' (6-component layouts need 6, FULL_9 needs 9, TEEM_7 7).");
    return 0;
  }

  if (association != vtkDataObject::FIELD_ASSOCIATION_CELLS &&
    association != vtkDataObject::FIELD_ASSOCIATION_POINTS)
  {
    vtkErrorMacro("The tensor array must be point or cell data.");
    return 0;
  }
  vtkDataSetAttributes* attributes = association == vtkDataObject::FIELD_ASSOCIATION_CELLS
    ? static_cast<vtkDataSetAttributes*>(output->GetCellData())
    : static_cast<vtkDataSetAttributes*>(output->GetPointData());

  const vtkIdType n = tensors->GetNumberOfTuples();
  const bool dbl = tensors->GetDataType() == VTK_DOUBLE;
  std::vector<vtkSmartPointer<vtkDataArray>> arrays;
  arrays.push_back(NewArray(dbl, "Eigenvalues", 3, n));
  arrays.push_back(NewArray(dbl, "Eigenvector1", 3, n));
  arrays.push_back(this->ComputeAllEigenvectors ? NewArray(dbl, "Eigenvector2", 3, n) : nullptr);
  arrays.push_back(this->ComputeAllEigenvectors ? NewArray(dbl, "Eigenvector3", 3, n) : nullptr);
  arrays.push_back(NewArray(dbl, "FractionalAnisotropy", 1, n));
  arrays.push_back(NewArray(dbl, "MeanDiffusivity", 1, n));
  arrays.push_back(NewArray(dbl, "LinearAnisotropy", 1, n));
  arrays.push_back(NewArray(dbl, "PlanarAnisotropy", 1, n));
  arrays.push_back(NewArray(dbl, "SphericalAnisotropy", 1, n));
  arrays.push_back(layout == TM::TEEM_7 ? NewArray(dbl, "Confidence", 1, n) : nullptr);
  arrays.push_back(NewArray(dbl, "ShapeCoordinates", 2, n));
  std::vector<vtkDataArray*> raw;
  for (auto& a : arrays)
  {
    raw.push_back(a.GetPointer());
  }

  this->NumberOfInvalidTensors =
    dbl ? Run<double>(tensors, layout, raw, this) : Run<float>(tensors, layout, raw, this);
  if (this->NumberOfInvalidTensors < 0)
  {
    this->NumberOfInvalidTensors = 0;
    output->Initialize(); // aborted: a clean, empty output
    return 1;
  }
  if (this->NumberOfInvalidTensors > 0)
  {
    vtkWarningMacro(<< this->NumberOfInvalidTensors << " of " << n
                    << " tensors have NaN or infinite components; their outputs are NaN.");
  }

  for (auto& a : arrays)
  {
    if (a)
    {
      attributes->AddArray(a);
    }
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkTensorAnalysisFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TensorLayout: " << this->TensorLayout << " ("
     << TM::GetLayoutName(this->TensorLayout) << ")\n";
  os << indent << "ComputeAllEigenvectors: " << this->ComputeAllEigenvectors << "\n";
  os << indent << "NumberOfInvalidTensors: " << this->NumberOfInvalidTensors << "\n";
}
