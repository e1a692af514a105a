// SPDX-License-Identifier: BSD-3-Clause
/**
 * vtkSplineVizSeeds: the seed port the tracers (vtkLRSplineStreamTracer,
 * vtkTensorLineTracer) share, vtkStreamTracer's "Source": port 1, optional,
 * the points of any data set or of every data set of a composite are the
 * seeds; the field (port 0) is requested whole in every piece and the seeds
 * are split like the output.
 *
 * Header-only, private to the module.
 */
#ifndef vtkSplineVizSeeds_h
#define vtkSplineVizSeeds_h

#include "vtkAlgorithm.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataSet.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <vector>

namespace vtkSplineVizSeeds
{
/// The number of seeds (points) of a data set or of a composite's data sets.
inline double Count(vtkDataObject* seeds)
{
  double count = 0.0;
  for (vtkDataSet* ds : vtkCompositeDataSet::GetDataSets(seeds))
  {
    count += static_cast<double>(ds->GetNumberOfPoints());
  }
  return count;
}

/// Appends the seeds' coordinates (x, y, z each) in the order of the data sets.
inline void Collect(vtkDataObject* seeds, std::vector<double>& xyz)
{
  for (vtkDataSet* ds : vtkCompositeDataSet::GetDataSets(seeds))
  {
    const vtkIdType n = ds->GetNumberOfPoints();
    for (vtkIdType i = 0; i < n; ++i)
    {
      double x[3];
      ds->GetPoint(i, x);
      xyz.insert(xyz.end(), x, x + 3);
    }
  }
}

/// FillInputPortInformation of the seed port: any data object, optional.
inline void FillPortInformation(vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataObject");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
}

/// RequestUpdateExtent of a tracer: the whole field (port 0, the whole
/// extent of an image) in every piece; the seeds (port 1, when connected)
/// split like the output.
inline void RequestUpdateExtent(
  vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  using SDDP = vtkStreamingDemandDrivenPipeline;
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  if (vtkInformation* fieldInfo = inputVector[0]->GetInformationObject(0))
  {
    fieldInfo->Set(SDDP::UPDATE_PIECE_NUMBER(), 0);
    fieldInfo->Set(SDDP::UPDATE_NUMBER_OF_PIECES(), 1);
    fieldInfo->Set(SDDP::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
    if (fieldInfo->Has(SDDP::WHOLE_EXTENT()))
    {
      fieldInfo->Set(SDDP::UPDATE_EXTENT(), fieldInfo->Get(SDDP::WHOLE_EXTENT()), 6);
    }
  }
  if (vtkInformation* seedInfo = inputVector[1]->GetInformationObject(0))
  {
    seedInfo->Set(SDDP::UPDATE_PIECE_NUMBER(), outInfo->Get(SDDP::UPDATE_PIECE_NUMBER()));
    seedInfo->Set(SDDP::UPDATE_NUMBER_OF_PIECES(), outInfo->Get(SDDP::UPDATE_NUMBER_OF_PIECES()));
    seedInfo->Set(SDDP::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
  }
}
}

#endif
