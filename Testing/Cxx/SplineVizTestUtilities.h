// SPDX-License-Identifier: BSD-3-Clause
// Small helpers shared by the SplineViz C++ tests.
#ifndef SplineVizTestUtilities_h
#define SplineVizTestUtilities_h

#include <cmath>
#include <iostream>
#include <string>

/// Counts failed checks; a test returns EXIT_FAILURE when any failed.
struct SplineVizTestStatus
{
  int Failures = 0;
  void Fail(const std::string& what, const char* file, int line)
  {
    ++this->Failures;
    std::cerr << "ERROR: check failed: " << what << " (" << file << ":" << line << ")" << std::endl;
  }
  int Result() const { return this->Failures == 0 ? 0 : 1; }
};

#define SV_CHECK(status, condition)                                                                \
  do                                                                                               \
  {                                                                                                \
    if (!(condition))                                                                              \
    {                                                                                              \
      (status).Fail(#condition, __FILE__, __LINE__);                                               \
    }                                                                                              \
  } while (0)

#define SV_CHECK_MSG(status, condition, message)                                                   \
  do                                                                                               \
  {                                                                                                \
    if (!(condition))                                                                              \
    {                                                                                              \
      std::cerr << "  " << message << std::endl;                                                   \
      (status).Fail(#condition, __FILE__, __LINE__);                                               \
    }                                                                                              \
  } while (0)

#define SV_CHECK_NEAR(status, a, b, tol)                                                           \
  do                                                                                               \
  {                                                                                                \
    const double sv_a_ = (a);                                                                      \
    const double sv_b_ = (b);                                                                      \
    if (!(std::abs(sv_a_ - sv_b_) <= (tol)))                                                       \
    {                                                                                              \
      std::cerr << "  " << #a << " = " << sv_a_ << ", " << #b << " = " << sv_b_ << ", tolerance "  \
                << (tol) << std::endl;                                                             \
      (status).Fail(#a " ~= " #b, __FILE__, __LINE__);                                             \
    }                                                                                              \
  } while (0)

#endif
