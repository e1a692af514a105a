// SPDX-License-Identifier: BSD-3-Clause
/**
 * Progress, abort and size checks shared by the SplineViz filters and readers.
 *
 * - vtkSplineVizProgress::For(): a vtkSMPTools::For over [first, last) run in
 *   a few batches (at most about 25, i.e. 4 % steps of the progress bar, each
 *   large enough to keep all threads busy): between batches, on the calling thread, the algorithm's
 *   UpdateProgress() (so ParaView's progress bar moves and Python sees
 *   vtkCommand::ProgressEvent) and CheckAbort() (AbortExecute, or an abort
 *   upstream). The worker threads never touch the algorithm, and the cost is
 *   one thread-pool round trip per batch. Functors with vtkSMPThreadLocal
 *   state work unchanged (the thread-local objects outlive the batches); a
 *   functor with Initialize()/Reduce() must not be passed (Reduce would run
 *   once per batch).
 * - vtkSplineVizProgress::CheckOutputSize(): refuse an output before
 *   allocating it when it could not fit in this machine's memory (a request
 *   such as 100000^3 samples or 10^9 seeds), with a message that says what
 *   was asked.
 *
 * Header-only, private to the module.
 */
#ifndef vtkSplineVizProgress_h
#define vtkSplineVizProgress_h

#include "vtkAlgorithm.h"
#include "vtkSMPTools.h"
#include "vtkType.h"

#include <vtksys/SystemInformation.hxx>

#include <algorithm>
#include <cstdint>
#include <sstream>
#include <string>

namespace vtkSplineVizProgress
{
/**
 * Run `body(begin, end)` over [first, last) with vtkSMPTools (grain `grain`,
 * 0 for vtkSMPTools' default), in batches of at least `minimumBatch` items,
 * reporting progress from `from` to `to` and checking for abort between
 * batches. Returns false when the algorithm was aborted (the remaining items
 * are not processed). `algorithm` may be null (one plain vtkSMPTools::For).
 */
template <typename Body>
bool For(vtkAlgorithm* algorithm, vtkIdType first, vtkIdType last, vtkIdType grain,
  vtkIdType minimumBatch, Body&& body, double from = 0.0, double to = 1.0)
{
  const vtkIdType n = last - first;
  if (n <= 0)
  {
    return !(algorithm && algorithm->CheckAbort());
  }
  if (!algorithm)
  {
    if (grain > 0)
    {
      vtkSMPTools::For(first, last, grain, body);
    }
    else
    {
      vtkSMPTools::For(first, last, body);
    }
    return true;
  }
  const vtkIdType threads = std::max(1, vtkSMPTools::GetEstimatedNumberOfThreads());
  const vtkIdType perBatch =
    std::max<vtkIdType>({ (n + 24) / 25, minimumBatch, threads * std::max<vtkIdType>(grain, 1) });
  for (vtkIdType begin = first; begin < last;)
  {
    if (algorithm->CheckAbort())
    {
      return false;
    }
    const vtkIdType end = std::min(last, begin + perBatch);
    if (grain > 0)
    {
      vtkSMPTools::For(begin, end, grain, body);
    }
    else
    {
      vtkSMPTools::For(begin, end, body);
    }
    algorithm->UpdateProgress(from + (to - from) * static_cast<double>(end - first) / n);
    begin = end;
  }
  return !algorithm->CheckAbort();
}

/// The memory an output may take: this machine's physical memory (cached).
inline double GetMemoryLimit()
{
  static const double limit = []()
  {
    vtksys::SystemInformation info;
    const double total = static_cast<double>(info.GetHostMemoryTotal()) * 1024.0; // KiB
    return total > 0 ? total : 64.0 * 1024 * 1024 * 1024;
  }();
  return limit;
}

/**
 * Refuse an output of `items` items of `bytesPerItem` bytes each when it is
 * more than this machine's memory (or more items than vtkIdType can count):
 * false with a message naming `what` and the sizes.
 */
inline bool CheckOutputSize(double items, double bytesPerItem, const char* what, std::string* error)
{
  const double bytes = items * bytesPerItem;
  const double limit = GetMemoryLimit();
  if (items < static_cast<double>(VTK_ID_MAX) && bytes <= limit)
  {
    return true;
  }
  if (error)
  {
    std::ostringstream msg;
    msg.precision(3);
    msg << what << " would take " << items << " items, about " << bytes / (1024.0 * 1024 * 1024)
        << " GiB, more than this machine's " << limit / (1024.0 * 1024 * 1024)
        << " GiB of memory: refused before allocating anything";
    *error = msg.str();
  }
  return false;
}
}

#endif
// VTK-HeaderTest-Exclude: vtkSplineVizProgress.h
