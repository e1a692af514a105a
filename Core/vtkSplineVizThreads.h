// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkSplineVizThreads
 * @brief   All cores by default: the vtkSMPTools backend SplineViz's parallel
 * loops (readers, tracers, fitting, the renderers' per-view work) run on.
 *
 * VTK as Debian builds it for ParaView 5.11 (and as many builds leave it)
 * compiles the STDThread backend but selects Sequential unless the
 * environment variable VTK_SMP_BACKEND_IN_USE names another, and ParaView
 * 5.11 does not change it: in the ParaView GUI, pvpython or plain Python,
 * every vtkSMPTools loop would run on one core. When SplineViz::Core's
 * library loads (every SplineViz module links it), UseAllCoresByDefault()
 * therefore switches a process that runs the Sequential default to
 * STDThread, with one thread per core, or per core and MPI rank on this node
 * when the MPI launcher says how many ranks share it
 * (OMPI_COMM_WORLD_LOCAL_SIZE, MPI_LOCALNRANKS), so that ranks do not
 * oversubscribe the cores (one core per rank keeps Sequential).
 *
 * A choice the user made is kept: with VTK_SMP_BACKEND_IN_USE set (to
 * Sequential for one thread, say) or a backend other than Sequential already
 * selected, nothing changes; VTK_SMP_MAX_THREADS, when set, caps the threads.
 *
 * Plain C++, private to the module.
 */
#ifndef vtkSplineVizThreads_h
#define vtkSplineVizThreads_h

#include <string>

class vtkSplineVizThreads
{
public:
  /**
   * Switch the Sequential default to STDThread as described above; returns
   * what was done (for logs and tests). Called once when the library loads;
   * calling it again changes nothing more.
   */
  static std::string UseAllCoresByDefault();

  /**
   * The threads per process for `cores` cores shared by `localRanks` MPI
   * ranks (at least 1).
   */
  static int ThreadsPerRank(int cores, int localRanks);
};

#endif
// VTK-HeaderTest-Exclude: vtkSplineVizThreads.h
