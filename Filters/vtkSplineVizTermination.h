// SPDX-License-Identifier: BSD-3-Clause
/**
 * Why a traced line ended: one set of codes for both tracers
 * (vtkLRSplineStreamTracer, vtkTensorLineTracer), written to their
 * ReasonForTermination arrays. Codes 1-6 are vtkStreamTracer's, so that
 * scripts written for it read ours the same way; 7 and up are SplineViz's
 * (OUT_OF_TIME is vtkStreamTracer::FIXED_REASONS_FOR_TERMINATION_COUNT, the
 * first code it leaves to subclasses). The tracers' public ReasonForTermination
 * enums keep these values (checked at compile time).
 *
 * Header-only, private to the module.
 */
#ifndef vtkSplineVizTermination_h
#define vtkSplineVizTermination_h

namespace vtkSplineVizTermination
{
enum Reason : int
{
  OUT_OF_DOMAIN = 1,       ///< left the field's domain
  NOT_INITIALIZED = 2,     ///< the seed could not be evaluated
  UNEXPECTED_VALUE = 3,    ///< a NaN or infinite value
  OUT_OF_LENGTH = 4,       ///< MaximumPropagation (arc length)
  OUT_OF_STEPS = 5,        ///< MaximumNumberOfSteps
  STAGNATION = 6,          ///< no speed (vector field) or no direction (tensor field)
  OUT_OF_TIME = 7,         ///< MaximumIntegrationTime
  LOW_ANISOTROPY = 8,      ///< FA below the stopping threshold
  HIGH_CURVATURE = 9,      ///< turning angle above the maximum
  OUT_OF_MASK = 10,        ///< left the mask
  NEGATIVE_EIGENVALUE = 11 ///< an indefinite tensor under the stop policy
};

/// A short name of a code, for messages ("unknown" for others).
inline const char* Name(int reason)
{
  switch (reason)
  {
    case OUT_OF_DOMAIN:
      return "out of domain";
    case NOT_INITIALIZED:
      return "not initialized";
    case UNEXPECTED_VALUE:
      return "non-finite value";
    case OUT_OF_LENGTH:
      return "maximum length";
    case OUT_OF_STEPS:
      return "maximum number of steps";
    case STAGNATION:
      return "stagnation (no speed or no direction)";
    case OUT_OF_TIME:
      return "maximum integration time";
    case LOW_ANISOTROPY:
      return "FA below threshold";
    case HIGH_CURVATURE:
      return "turning angle above maximum";
    case OUT_OF_MASK:
      return "out of mask";
    case NEGATIVE_EIGENVALUE:
      return "negative eigenvalue";
    default:
      return "unknown";
  }
}
}

#endif
// VTK-HeaderTest-Exclude: vtkSplineVizTermination.h
