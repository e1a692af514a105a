// SPDX-License-Identifier: BSD-3-Clause
/**
 * vtkSplineVizRungeKutta: the explicit Runge-Kutta integrator of both tracers
 * (vtkLRSplineStreamTracer, vtkTensorLineTracer): the Butcher tableaux
 * (Euler, midpoint, Kutta's third order, classic RK4, the 3/8 rule,
 * Fehlberg's fifth order and the embedded pairs Heun-Euler 2(1),
 * Bogacki-Shampine 3(2), Fehlberg 4(5)) and one step.
 *
 * Step() evaluates stage i at x + h sum_j a_ij k_j through a derivative
 * functor f(i, x_i, ref, k_i) that returns 0 or a status. `ref` is a
 * reference direction: the step's incoming direction for stage 0, the first
 * stage's k for the others. A vector field ignores it; a direction field
 * (a tensor's principal eigenvector, which has no sign) turns its direction
 * to agree with it, so that the stages of one step never cancel. A stage's
 * nonzero status ends the step and is returned unchanged. Embedded pairs also
 * give the error estimate |h sum_j e_j k_j|, e = b - b_hat; step-size control
 * is the caller's. The weights are fractions, or integers over a common
 * denominator (OverDenominator()): the two forms round differently.
 *
 * Header-only, private to the module.
 */
#ifndef vtkSplineVizRungeKutta_h
#define vtkSplineVizRungeKutta_h

#include <cmath>

namespace vtkSplineVizRungeKutta
{
/// The methods; vtkLRSplineStreamTracer's Integrators have these values.
enum Method : int
{
  EULER = 0,            ///< RK1, order 1
  MIDPOINT = 1,         ///< RK2, k2 at x + h/2 k1, order 2
  KUTTA3 = 2,           ///< RK3, order 3
  RUNGE_KUTTA4 = 3,     ///< classic RK4, order 4
  RUNGE_KUTTA4_38 = 4,  ///< 3/8 rule, order 4
  RKF5 = 5,             ///< Fehlberg's fifth-order solution, no error estimate
  HEUN_EULER = 6,       ///< embedded 2(1)
  BOGACKI_SHAMPINE = 7, ///< embedded 3(2)
  RKF45 = 8             ///< embedded 4(5), fifth order propagated
};

constexpr int MaxStages = 6;

/// An explicit Butcher tableau. B / BDenominator: the propagated solution's
/// weights b; E: b - b_hat, the error estimate's weights (embedded pairs only).
struct Tableau
{
  int Stages = 0;
  double A[MaxStages][MaxStages] = {};
  double B[MaxStages] = {};
  double BDenominator = 1.0; ///< 1, or the common denominator of OverDenominator()
  double E[MaxStages] = {};
  int Order = 0;      ///< of the propagated solution
  int ErrorOrder = 0; ///< of the lower solution (controller exponent 1 / (q + 1))
  bool Embedded = false;
};

/// The tableau of a Method (RKF5's for unknown values).
inline Tableau MakeTableau(int method)
{
  Tableau t;
  switch (method)
  {
    case EULER:
      t.Stages = 1;
      t.B[0] = 1.0;
      t.Order = 1;
      break;
    case MIDPOINT:
      t.Stages = 2;
      t.A[1][0] = 0.5;
      t.B[1] = 1.0;
      t.Order = 2;
      break;
    case KUTTA3:
      t.Stages = 3;
      t.A[1][0] = 0.5;
      t.A[2][0] = -1.0;
      t.A[2][1] = 2.0;
      t.B[0] = 1.0 / 6.0;
      t.B[1] = 2.0 / 3.0;
      t.B[2] = 1.0 / 6.0;
      t.Order = 3;
      break;
    case RUNGE_KUTTA4:
      t.Stages = 4;
      t.A[1][0] = 0.5;
      t.A[2][1] = 0.5;
      t.A[3][2] = 1.0;
      t.B[0] = t.B[3] = 1.0 / 6.0;
      t.B[1] = t.B[2] = 1.0 / 3.0;
      t.Order = 4;
      break;
    case RUNGE_KUTTA4_38:
      t.Stages = 4;
      t.A[1][0] = 1.0 / 3.0;
      t.A[2][0] = -1.0 / 3.0;
      t.A[2][1] = 1.0;
      t.A[3][0] = 1.0;
      t.A[3][1] = -1.0;
      t.A[3][2] = 1.0;
      t.B[0] = t.B[3] = 1.0 / 8.0;
      t.B[1] = t.B[2] = 3.0 / 8.0;
      t.Order = 4;
      break;
    case HEUN_EULER:
      t.Stages = 2;
      t.A[1][0] = 1.0;
      t.B[0] = t.B[1] = 0.5;
      // b_hat = (1, 0)
      t.E[0] = 0.5 - 1.0;
      t.E[1] = 0.5;
      t.Order = 2;
      t.ErrorOrder = 1;
      t.Embedded = true;
      break;
    case BOGACKI_SHAMPINE:
    {
      t.Stages = 4;
      t.A[1][0] = 0.5;
      t.A[2][1] = 0.75;
      t.A[3][0] = 2.0 / 9.0;
      t.A[3][1] = 1.0 / 3.0;
      t.A[3][2] = 4.0 / 9.0;
      const double b3[4] = { 2.0 / 9.0, 1.0 / 3.0, 4.0 / 9.0, 0.0 };
      const double b2[4] = { 7.0 / 24.0, 1.0 / 4.0, 1.0 / 3.0, 1.0 / 8.0 };
      for (int i = 0; i < 4; ++i)
      {
        t.B[i] = b3[i];
        t.E[i] = b3[i] - b2[i];
      }
      t.Order = 3;
      t.ErrorOrder = 2;
      t.Embedded = true;
      break;
    }
    case RKF5:
    case RKF45:
    default:
    {
      t.Stages = 6;
      t.A[1][0] = 1.0 / 4.0;
      t.A[2][0] = 3.0 / 32.0;
      t.A[2][1] = 9.0 / 32.0;
      t.A[3][0] = 1932.0 / 2197.0;
      t.A[3][1] = -7200.0 / 2197.0;
      t.A[3][2] = 7296.0 / 2197.0;
      t.A[4][0] = 439.0 / 216.0;
      t.A[4][1] = -8.0;
      t.A[4][2] = 3680.0 / 513.0;
      t.A[4][3] = -845.0 / 4104.0;
      t.A[5][0] = -8.0 / 27.0;
      t.A[5][1] = 2.0;
      t.A[5][2] = -3544.0 / 2565.0;
      t.A[5][3] = 1859.0 / 4104.0;
      t.A[5][4] = -11.0 / 40.0;
      const double b5[6] = { 16.0 / 135.0, 0.0, 6656.0 / 12825.0, 28561.0 / 56430.0, -9.0 / 50.0,
        2.0 / 55.0 };
      const double b4[6] = { 25.0 / 216.0, 0.0, 1408.0 / 2565.0, 2197.0 / 4104.0, -1.0 / 5.0, 0.0 };
      for (int i = 0; i < 6; ++i)
      {
        t.B[i] = b5[i];
        t.E[i] = b5[i] - b4[i];
      }
      t.Order = 5;
      t.ErrorOrder = 4;
      t.Embedded = (method == RKF45);
      break;
    }
  }
  return t;
}

/// The same tableau with its weights written over a common denominator d:
/// integers B_j = b_j d, summed as (h / d) sum_j B_j k_j (classic RK4 over 6:
/// h / 6 (k_1 + 2 k_2 + 2 k_3 + k_4)). Its steps differ from those of the
/// fractions b_j in the last bit only, which is enough to move a point that
/// lands exactly on a threshold to the other side: a tracer keeps one form.
inline Tableau OverDenominator(Tableau t, double d)
{
  for (int j = 0; j < t.Stages; ++j)
  {
    t.B[j] = std::round(t.B[j] / t.BDenominator * d);
  }
  t.BDenominator = d;
  return t;
}

/// A short name of a Method, for messages ("unknown" for others).
inline const char* Name(int method)
{
  switch (method)
  {
    case EULER:
      return "RK1 (explicit Euler)";
    case MIDPOINT:
      return "RK2 (midpoint)";
    case KUTTA3:
      return "RK3 (Kutta)";
    case RUNGE_KUTTA4:
      return "RK4 (classic)";
    case RUNGE_KUTTA4_38:
      return "RK4 3/8 rule";
    case RKF5:
      return "RKF5 (Fehlberg, 5th order)";
    case HEUN_EULER:
      return "Heun-Euler 2(1)";
    case BOGACKI_SHAMPINE:
      return "Bogacki-Shampine 3(2)";
    case RKF45:
      return "RKF45 (Fehlberg 4(5))";
    default:
      return "unknown";
  }
}

/**
 * One step of size h (signed) from x: out = x + (h / BDenominator) sum_i
 * B_i k_i, with k_i = f(i, x + h sum_{j<i} a_ij k_j, ref_i) and ref_0 = `in` (the step's
 * incoming direction), ref_i = k_0 for i > 0. `f` is callable as
 * `int f(int stage, const S xs[3], const S ref[3], S k[3])` and returns 0
 * or a status; stage 0 is evaluated at x itself (a caller that knows f(x)
 * may return it). Returns 0, or the first nonzero status of a stage (then
 * `out` and `error` are not written). `error`, when given: the embedded
 * pair's error estimate |h sum_i e_i k_i| (0 for the other tableaux). S is
 * the state's precision (coefficients are rounded to it).
 */
template <typename S, typename Derivative>
int Step(
  const Tableau& T, const S x[3], const S in[3], S h, Derivative&& f, S out[3], S* error = nullptr)
{
  S k[MaxStages][3];
  for (int i = 0; i < T.Stages; ++i)
  {
    S xs[3];
    for (int d = 0; d < 3; ++d)
    {
      S acc = S(0);
      for (int j = 0; j < i; ++j)
      {
        acc += static_cast<S>(T.A[i][j]) * k[j][d];
      }
      xs[d] = i == 0 ? x[d] : x[d] + h * acc;
    }
    const int status = f(i, static_cast<const S*>(xs), i == 0 ? in : k[0], k[i]);
    if (status != 0)
    {
      return status;
    }
  }
  const S hb = h / static_cast<S>(T.BDenominator); // h when BDenominator = 1
  S err2 = S(0);
  for (int d = 0; d < 3; ++d)
  {
    S acc = S(0), e = S(0);
    for (int j = 0; j < T.Stages; ++j)
    {
      acc += static_cast<S>(T.B[j]) * k[j][d];
      if (T.Embedded)
      {
        e += static_cast<S>(T.E[j]) * k[j][d];
      }
    }
    out[d] = x[d] + hb * acc;
    err2 += (h * e) * (h * e);
  }
  if (error)
  {
    *error = std::sqrt(err2);
  }
  return 0;
}
}

#endif
// VTK-HeaderTest-Exclude: vtkSplineVizRungeKutta.h
