// SPDX-License-Identifier: BSD-3-Clause
/**
 * The piece of its output an update asks an algorithm for, as ParaView's
 * parallel pipeline sets it (UPDATE_PIECE_NUMBER of UPDATE_NUMBER_OF_PIECES):
 * shared by the readers and filters that make only their piece; and the
 * request for all of an input, shared by those that need all of it.
 *
 * Header-only, private to the module.
 */
#ifndef vtkSplineVizPieces_h
#define vtkSplineVizPieces_h

#include "vtkInformation.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>

namespace vtkSplineVizPieces
{
/**
 * The requested piece and number of pieces of `outInfo`, the piece clamped to
 * [0, numberOfPieces); piece 0 of 1 when the request names none.
 */
inline void GetRequested(vtkInformation* outInfo, int& piece, int& numberOfPieces)
{
  piece = 0;
  numberOfPieces = 1;
  if (outInfo && outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()))
  {
    numberOfPieces =
      std::max(1, outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()));
    piece = std::max(0,
      std::min(
        outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()), numberOfPieces - 1));
  }
}

/**
 * Asks an input (`inInfo`, may be null) for all of its data, whatever piece
 * of the output is requested: piece 0 of 1, no ghost levels, and for
 * structured data its whole extent. For the algorithms that need the whole
 * input on every rank (the fitters, the spline sources of probes and
 * resampling).
 */
inline void RequestWholeInput(vtkInformation* inInfo)
{
  if (!inInfo)
  {
    return;
  }
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
  if (inInfo->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
  {
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(),
      inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()), 6);
  }
}
}

#endif
