// SPDX-License-Identifier: BSD-3-Clause
/**
 * vtkSplineVizPolyLines: the output the synthetic sources share: the items
 * (tubes, streamlines) of the requested piece, and one polyline per item
 * with its points consecutive in float points (connectivity 0, 1, 2, ...).
 *
 * Header-only, private to the module.
 */
#ifndef vtkSplineVizPolyLines_h
#define vtkSplineVizPolyLines_h

#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>

class vtkSplineVizPolyLines
{
public:
  /// The items [first, end) of `total` that the requested piece of `outInfo` holds.
  static void PieceRange(vtkInformation* outInfo, vtkIdType total, vtkIdType& first, vtkIdType& end)
  {
    int piece = 0;
    int pieces = 1;
    if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()))
    {
      piece = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER());
      pieces =
        std::max(1, outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()));
    }
    first = total * piece / pieces;
    end = total * (piece + 1) / pieces;
  }

  /// Allocates `lines` polylines, line i of `pointsOf(i)` points.
  template <typename PointsOf>
  void Allocate(vtkIdType lines, PointsOf&& pointsOf)
  {
    this->Offsets->SetNumberOfTuples(lines + 1);
    vtkIdType* offset = this->Offsets->GetPointer(0);
    offset[0] = 0;
    for (vtkIdType i = 0; i < lines; ++i)
    {
      offset[i + 1] = offset[i] + pointsOf(i);
    }
    const vtkIdType n = offset[lines];
    this->Points->SetDataTypeToFloat();
    this->Points->SetNumberOfPoints(n);
    this->Xyz = static_cast<vtkFloatArray*>(this->Points->GetData())->GetPointer(0);
    this->Connectivity->SetNumberOfTuples(n);
    vtkIdType* connectivity = this->Connectivity->GetPointer(0);
    vtkSMPTools::For(0, n,
      [connectivity](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType k = begin; k < end; ++k)
        {
          connectivity[k] = k;
        }
      });
  }

  vtkIdType GetNumberOfPoints() const { return this->Points->GetNumberOfPoints(); }
  /// The first point of line i (i = lines: the number of points).
  vtkIdType GetOffset(vtkIdType i) const { return this->Offsets->GetValue(i); }
  /// Sets point `id` (thread-safe for distinct ids).
  void SetPoint(vtkIdType id, double x, double y, double z)
  {
    float* xyz = this->Xyz + 3 * id;
    xyz[0] = static_cast<float>(x);
    xyz[1] = static_cast<float>(y);
    xyz[2] = static_cast<float>(z);
  }

  /// Gives `output` the points and the lines.
  void SetOutput(vtkPolyData* output)
  {
    vtkNew<vtkCellArray> lines;
    lines->SetData(this->Offsets, this->Connectivity);
    output->SetPoints(this->Points);
    output->SetLines(lines);
  }

private:
  vtkNew<vtkPoints> Points;
  vtkNew<vtkIdTypeArray> Offsets;
  vtkNew<vtkIdTypeArray> Connectivity;
  float* Xyz = nullptr;
};

#endif
