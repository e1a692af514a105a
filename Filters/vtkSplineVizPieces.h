// SPDX-License-Identifier: BSD-3-Clause
/**
 * The piece of its output an update asks an algorithm for, as ParaView's
 * parallel pipeline sets it (UPDATE_PIECE_NUMBER of UPDATE_NUMBER_OF_PIECES):
 * shared by the readers and filters that make only their piece.
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
}

#endif
