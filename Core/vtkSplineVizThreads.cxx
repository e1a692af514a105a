// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSplineVizThreads.h"

#include "vtkSMPTools.h"

#include <algorithm>
#include <cstdlib>
#include <string>
#include <thread>

namespace
{
/// A positive integer from the environment, or 0.
int EnvironmentCount(const char* name)
{
  const char* value = std::getenv(name);
  if (!value || !*value)
  {
    return 0;
  }
  char* end = nullptr;
  const long n = std::strtol(value, &end, 10);
  return (end && *end == '\0' && n > 0 && n < (1L << 24)) ? static_cast<int>(n) : 0;
}

/// What UseAllCoresByDefault() did when the library loaded.
const std::string LoadTimeChoice = vtkSplineVizThreads::UseAllCoresByDefault();
}

//------------------------------------------------------------------------------
int vtkSplineVizThreads::ThreadsPerRank(int cores, int localRanks)
{
  return std::max(1, std::max(cores, 1) / std::max(localRanks, 1));
}

//------------------------------------------------------------------------------
std::string vtkSplineVizThreads::UseAllCoresByDefault()
{
  if (std::getenv("VTK_SMP_BACKEND_IN_USE"))
  {
    return "kept: VTK_SMP_BACKEND_IN_USE is set";
  }
  const char* backend = vtkSMPTools::GetBackend();
  if (!backend || std::string(backend) != "Sequential")
  {
    return std::string("kept: backend ") + (backend ? backend : "(none)");
  }
  int localRanks = EnvironmentCount("OMPI_COMM_WORLD_LOCAL_SIZE");
  if (localRanks == 0)
  {
    localRanks = EnvironmentCount("MPI_LOCALNRANKS");
  }
  const int cores = static_cast<int>(std::thread::hardware_concurrency());
  int threads = ThreadsPerRank(cores, localRanks);
  if (const int cap = EnvironmentCount("VTK_SMP_MAX_THREADS"))
  {
    threads = std::min(threads, cap);
  }
  if (threads <= 1)
  {
    return "kept: Sequential (one core per process)";
  }
  if (!vtkSMPTools::SetBackend("STDThread"))
  {
    return "kept: Sequential (no STDThread backend in this VTK)";
  }
  vtkSMPTools::Initialize(threads);
  return "STDThread with " + std::to_string(threads) + " threads";
}
