// SPDX-License-Identifier: BSD-3-Clause
// The Runge-Kutta integrator both tracers share (vtkSplineVizRungeKutta.h),
// on ODEs with known solutions:
//  - every tableau converges at its order, forward and backward (negative
//    h): the global error at the end of a non-linear system (y1' = y1^2,
//    y2' = -y1 y2, y3' = cos y3) and of a growing rotation (y' = M y) falls
//    by 2^order when h is halved (observed order within 0.25);
//  - the embedded pairs' error estimate of one step falls like h^(q+1) and
//    exceeds the step's true error; the other tableaux report 0;
//  - a failing stage's status is returned unchanged, later stages are not
//    evaluated and nothing is written;
//  - the reference direction is the incoming one for stage 0 and stage 0's
//    k for the others: a direction field of arbitrary signs turned like it
//    steps exactly like the oriented field (without turning it does not);
//  - weights over a common denominator (RK4: (1, 2, 2, 1) / 6) are the
//    integers, converge at the order and step like the fractions but for
//    rounding;
//  - negative controls: each tableau with one coefficient off by 0.05
//    converges at order 1 (Euler's: not at all), which the order check
//    rejects; float states.
#include "vtkSplineVizRungeKutta.h"

#include "SplineVizTestUtilities.h"

#include <array>
#include <cmath>
#include <functional>
#include <iomanip>
#include <iostream>
#include <limits>
#include <string>

namespace
{
namespace RK = vtkSplineVizRungeKutta;
using Vec = std::array<double, 3>;

struct Problem
{
  const char* Name;
  std::function<void(const double y[3], double f[3])> F;
  std::function<Vec(double t)> Exact;
  double T;
};

// gd(u) = 2 atan(tanh(u / 2)), the Gudermannian: gd' = cos(gd).
double Gd(double u)
{
  return 2.0 * std::atan(std::tanh(0.5 * u));
}

Problem NonLinear()
{
  // y1 = 0.25 / (1 - 0.25 t), y2 = 1 - 0.25 t, y3 = gd(t + gd^-1(0.2))
  const double u0 = 2.0 * std::atanh(std::tan(0.1));
  return { "non-linear",
    [](const double y[3], double f[3])
    {
      f[0] = y[0] * y[0];
      f[1] = -y[0] * y[1];
      f[2] = std::cos(y[2]);
    },
    [u0](double t) -> Vec {
      return { 0.25 / (1.0 - 0.25 * t), 1.0 - 0.25 * t, Gd(t + u0) };
    },
    2.0 };
}

Problem Rotation()
{
  // M = [[0.1, -1, 0], [1, 0.1, 0], [0, 0, -0.5]], y(0) = (1, 0.5, 2)
  return { "rotation",
    [](const double y[3], double f[3])
    {
      f[0] = 0.1 * y[0] - y[1];
      f[1] = y[0] + 0.1 * y[1];
      f[2] = -0.5 * y[2];
    },
    [](double t) -> Vec
    {
      const double g = std::exp(0.1 * t), c = std::cos(t), s = std::sin(t);
      return { g * (c * 1.0 - s * 0.5), g * (s * 1.0 + c * 0.5), 2.0 * std::exp(-0.5 * t) };
    },
    2.0 };
}

double Distance(const Vec& a, const Vec& b)
{
  return std::sqrt(
    (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

// The error at the end of n steps from one end of [0, T] to the other.
double GlobalError(const RK::Tableau& T, const Problem& p, int n, bool backward)
{
  Vec y = p.Exact(backward ? p.T : 0.0);
  const double h = (backward ? -p.T : p.T) / n;
  auto f = [&p](int, const double* x, const double*, double* k)
  {
    p.F(x, k);
    return 0;
  };
  for (int i = 0; i < n; ++i)
  {
    Vec next;
    if (RK::Step(T, y.data(), y.data(), h, f, next.data()) != 0)
    {
      return std::numeric_limits<double>::quiet_NaN();
    }
    y = next;
  }
  return Distance(y, p.Exact(backward ? 0.0 : p.T));
}

// Observed orders log2(E(h) / E(h / 2)) for h = T / n0, T / 2n0, T / 4n0.
void ObservedOrders(
  const RK::Tableau& T, const Problem& p, int n0, bool backward, double& r1, double& r2)
{
  const double e0 = GlobalError(T, p, n0, backward);
  const double e1 = GlobalError(T, p, 2 * n0, backward);
  const double e2 = GlobalError(T, p, 4 * n0, backward);
  r1 = std::log2(e0 / e1);
  r2 = std::log2(e1 / e2);
}

// The order check: both observed orders within 0.25 of the expected one.
bool OrderMatches(double r1, double r2, int order)
{
  return std::abs(r1 - order) < 0.25 && std::abs(r2 - order) < 0.25;
}

// Steps small enough for the asymptotic regime (the fifth-order error
// terms of the non-linear system partly cancel at larger steps), large
// enough to stay far above rounding.
int StepsFor(int order)
{
  switch (order)
  {
    case 1:
      return 64;
    case 2:
      return 32;
    case 4:
      return 8;
    default:
      return 16;
  }
}

void TestOrders(SplineVizTestStatus& status)
{
  for (int m = RK::EULER; m <= RK::RKF45; ++m)
  {
    const RK::Tableau T = RK::MakeTableau(m);
    for (const Problem& p : { NonLinear(), Rotation() })
    {
      for (bool backward : { false, true })
      {
        double r1, r2;
        ObservedOrders(T, p, StepsFor(T.Order), backward, r1, r2);
        std::cout << std::left << std::setw(28) << RK::Name(m) << std::right << " " << p.Name
                  << (backward ? " backward" : " forward ") << ": observed orders "
                  << std::setprecision(3) << r1 << ", " << r2 << " (tableau " << T.Order << ")"
                  << std::endl;
        SV_CHECK_MSG(status, OrderMatches(r1, r2, T.Order),
          RK::Name(m) << " on " << p.Name << ": orders " << r1 << ", " << r2);
      }
    }
  }
}

// Negative controls: one coefficient off by 0.05 (in the last stage that
// the solution weighs; b_0 for Euler) breaks b^T c = 1/2 (sum b = 1 for
// Euler): first order (none for Euler), which the order check rejects.
void TestWrongTableaux(SplineVizTestStatus& status)
{
  const Problem p = NonLinear();
  for (int m = RK::EULER; m <= RK::RKF45; ++m)
  {
    RK::Tableau T = RK::MakeTableau(m);
    int row = 0;
    for (int i = 1; i < T.Stages; ++i)
    {
      row = T.B[i] != 0.0 ? i : row;
    }
    if (row > 0)
    {
      T.A[row][0] += 0.05;
    }
    else
    {
      T.B[0] += 0.05;
    }
    double r1, r2;
    ObservedOrders(T, p, StepsFor(T.Order), false, r1, r2);
    std::cout << "negative control, " << RK::Name(m) << " with "
              << (row > 0 ? "a_" + std::to_string(row) + "0" : std::string("b_0"))
              << " + 0.05: observed orders " << r1 << ", " << r2 << std::endl;
    SV_CHECK_MSG(
      status, !OrderMatches(r1, r2, T.Order), "the order check accepts a wrong " << RK::Name(m));
    const double expected = row > 0 ? 1.0 : 0.0;
    SV_CHECK_MSG(status, std::abs(r2 - expected) < 0.3,
      "a wrong " << RK::Name(m) << " converges at " << r2 << ", not " << expected);
  }
}

// One step's error estimate: |h sum e_i k_i| ~ h^(q+1) for the embedded
// pairs, above the step's true error; 0 for the others.
void TestErrorEstimate(SplineVizTestStatus& status)
{
  const Problem p = NonLinear();
  auto f = [&p](int, const double* x, const double*, double* k)
  {
    p.F(x, k);
    return 0;
  };
  const Vec y0 = p.Exact(0.0);
  for (int m = RK::EULER; m <= RK::RKF45; ++m)
  {
    const RK::Tableau T = RK::MakeTableau(m);
    double estimate[3], truth[3];
    for (int k = 0; k < 3; ++k)
    {
      const double h = 0.1 / (1 << k);
      Vec y1;
      estimate[k] = -1.0;
      RK::Step(T, y0.data(), y0.data(), h, f, y1.data(), &estimate[k]);
      truth[k] = Distance(y1, p.Exact(h));
    }
    if (!T.Embedded)
    {
      SV_CHECK_MSG(status, estimate[0] == 0.0 && estimate[2] == 0.0,
        RK::Name(m) << " reports an error estimate " << estimate[0]);
      continue;
    }
    const double r1 = std::log2(estimate[0] / estimate[1]);
    const double r2 = std::log2(estimate[1] / estimate[2]);
    std::cout << RK::Name(m) << ": error estimates " << std::setprecision(3) << estimate[0] << ", "
              << estimate[1] << ", " << estimate[2] << " (true local errors " << truth[0] << ", "
              << truth[1] << ", " << truth[2] << "), observed orders " << r1 << ", " << r2
              << " (expected " << T.ErrorOrder + 1 << ")" << std::endl;
    SV_CHECK_MSG(status, OrderMatches(r1, r2, T.ErrorOrder + 1),
      RK::Name(m) << " estimate orders " << r1 << ", " << r2);
    for (int k = 0; k < 3; ++k)
    {
      SV_CHECK_MSG(status, estimate[k] > truth[k],
        RK::Name(m) << " estimate " << estimate[k] << " below the true error " << truth[k]);
    }
  }
}

// A failing stage ends the step with its status.
void TestFailingStage(SplineVizTestStatus& status)
{
  const Problem p = Rotation();
  const Vec y0 = p.Exact(0.0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (int m = RK::EULER; m <= RK::RKF45; ++m)
  {
    const RK::Tableau T = RK::MakeTableau(m);
    for (int failAt = 0; failAt < T.Stages; ++failAt)
    {
      int calls = 0;
      auto f = [&](int stage, const double* x, const double*, double* k)
      {
        ++calls;
        p.F(x, k);
        return stage == failAt ? 42 + stage : 0;
      };
      Vec out = { nan, nan, nan };
      double error = -1.0;
      const int r = RK::Step(T, y0.data(), y0.data(), 0.1, f, out.data(), &error);
      SV_CHECK_MSG(status, r == 42 + failAt,
        RK::Name(m) << ": stage " << failAt << " fails, step returns " << r);
      SV_CHECK_MSG(status, calls == failAt + 1,
        RK::Name(m) << ": " << calls << " stages evaluated, the failing one is " << failAt);
      SV_CHECK(status, std::isnan(out[0]) && std::isnan(out[1]) && std::isnan(out[2]));
      SV_CHECK(status, error == -1.0);
    }
  }
}

// The reference directions, and a sign-free direction field turned like them.
void TestReferenceDirection(SplineVizTestStatus& status)
{
  for (int m = RK::EULER; m <= RK::RKF45; ++m)
  {
    const RK::Tableau T = RK::MakeTableau(m);
    // which reference each stage gets
    const double in[3] = { 0.3, -0.4, 0.5 }, x[3] = { 1.0, 2.0, 3.0 };
    Vec k0 = { 0, 0, 0 };
    bool refsOk = true;
    auto record = [&](int stage, const double* xs, const double* ref, double* k)
    {
      const Vec expected = stage == 0 ? Vec{ in[0], in[1], in[2] } : k0;
      refsOk = refsOk && ref[0] == expected[0] && ref[1] == expected[1] && ref[2] == expected[2];
      for (int d = 0; d < 3; ++d)
      {
        k[d] = std::sin(xs[d] + stage); // differs per stage
      }
      if (stage == 0)
      {
        k0 = { k[0], k[1], k[2] };
      }
      return 0;
    };
    double out[3];
    RK::Step(T, x, in, 0.25, record, out);
    SV_CHECK_MSG(status, refsOk, RK::Name(m) << ": wrong reference direction");

    // Circles about z: the tangent t(x) = (-y, x, 0) / r, returned with a
    // sign that flips at every call (like an eigen-solver's).
    auto tangent = [](const double* p, double* t)
    {
      const double r = std::hypot(p[0], p[1]);
      t[0] = -p[1] / r;
      t[1] = p[0] / r;
      t[2] = 0.0;
    };
    int calls = 0;
    auto signless = [&](bool turn)
    {
      return [&, turn](int, const double* xs, const double* ref, double* k)
      {
        tangent(xs, k);
        double sign = (++calls % 2) ? -1.0 : 1.0;
        if (turn && sign * (k[0] * ref[0] + k[1] * ref[1] + k[2] * ref[2]) < 0.0)
        {
          sign = -sign;
        }
        for (int d = 0; d < 3; ++d)
        {
          k[d] *= sign;
        }
        return 0;
      };
    };
    auto oriented = [&](int, const double* xs, const double*, double* k)
    {
      tangent(xs, k);
      return 0;
    };
    const double p0[3] = { 1.0, 0.0, 0.2 };
    double incoming[3];
    tangent(p0, incoming);
    double a[3], b[3], c[3];
    RK::Step(T, p0, incoming, 0.3, oriented, a);
    RK::Step(T, p0, incoming, 0.3, signless(true), b);
    RK::Step(T, p0, incoming, 0.3, signless(false), c);
    SV_CHECK_MSG(status, a[0] == b[0] && a[1] == b[1] && a[2] == b[2],
      RK::Name(m) << ": turned directions step differently from the oriented field");
    if (T.Stages > 1)
    {
      // negative control: without turning, the step goes elsewhere
      SV_CHECK_MSG(status, std::abs(a[0] - c[0]) + std::abs(a[1] - c[1]) > 1e-3,
        RK::Name(m) << ": the sign test cannot fail");
    }
  }
}

// Weights over a common denominator: the same method.
void TestDenominator(SplineVizTestStatus& status)
{
  struct Case
  {
    int Method;
    double D;
    double Numerators[4];
  };
  const Case cases[] = { { RK::RUNGE_KUTTA4, 6.0, { 1, 2, 2, 1 } },
    { RK::RUNGE_KUTTA4_38, 8.0, { 1, 3, 3, 1 } }, { RK::KUTTA3, 6.0, { 1, 4, 1, 0 } } };
  const Problem p = NonLinear();
  auto f = [&p](int, const double* x, const double*, double* k)
  {
    p.F(x, k);
    return 0;
  };
  for (const Case& c : cases)
  {
    const RK::Tableau fractions = RK::MakeTableau(c.Method);
    const RK::Tableau T = RK::OverDenominator(fractions, c.D);
    SV_CHECK(status, T.BDenominator == c.D);
    for (int j = 0; j < 4; ++j)
    {
      SV_CHECK_MSG(status, T.B[j] == c.Numerators[j],
        RK::Name(c.Method) << " over " << c.D << ": B_" << j << " = " << T.B[j]);
    }
    double r1, r2;
    ObservedOrders(T, p, StepsFor(T.Order), false, r1, r2);
    SV_CHECK_MSG(status, OrderMatches(r1, r2, T.Order),
      RK::Name(c.Method) << " over " << c.D << ": orders " << r1 << ", " << r2);
    const Vec y0 = p.Exact(0.0);
    Vec a, b;
    RK::Step(fractions, y0.data(), y0.data(), 0.1, f, a.data());
    RK::Step(T, y0.data(), y0.data(), 0.1, f, b.data());
    SV_CHECK_MSG(status, Distance(a, b) <= 1e-15,
      RK::Name(c.Method) << ": the forms differ by " << Distance(a, b));
  }
}

// A float state (the LR tracer's single precision) converges too.
void TestFloat(SplineVizTestStatus& status)
{
  const Problem p = Rotation();
  const RK::Tableau T = RK::MakeTableau(RK::RUNGE_KUTTA4);
  auto f = [&p](int, const float* x, const float*, float* k)
  {
    const double xd[3] = { x[0], x[1], x[2] };
    double kd[3];
    p.F(xd, kd);
    for (int d = 0; d < 3; ++d)
    {
      k[d] = static_cast<float>(kd[d]);
    }
    return 0;
  };
  const Vec e0 = p.Exact(0.0);
  float y[3] = { static_cast<float>(e0[0]), static_cast<float>(e0[1]), static_cast<float>(e0[2]) };
  const int n = 32;
  for (int i = 0; i < n; ++i)
  {
    float next[3];
    RK::Step(T, y, y, static_cast<float>(p.T / n), f, next);
    std::copy(next, next + 3, y);
  }
  const double err = Distance({ y[0], y[1], y[2] }, p.Exact(p.T));
  const double errDouble = GlobalError(T, p, n, false);
  std::cout << "RK4, float state, 32 steps: error " << err << " (double " << errDouble << ")"
            << std::endl;
  SV_CHECK(status, err < errDouble + 1e-5);
}
}

int TestSplineVizRungeKutta(int, char*[])
{
  SplineVizTestStatus status;
  // the tableaux' own data
  for (int m = RK::EULER; m <= RK::RKF45; ++m)
  {
    const RK::Tableau T = RK::MakeTableau(m);
    double sum = 0.0, sumE = 0.0;
    for (int i = 0; i < T.Stages; ++i)
    {
      sum += T.B[i];
      sumE += T.E[i];
      for (int j = i; j < RK::MaxStages; ++j)
      {
        SV_CHECK_MSG(status, T.A[i][j] == 0.0, RK::Name(m) << " is not explicit");
      }
    }
    SV_CHECK_NEAR(status, sum, 1.0, 1e-15);
    SV_CHECK_NEAR(status, sumE, 0.0, 1e-15);
    SV_CHECK(
      status, T.Embedded == (m == RK::HEUN_EULER || m == RK::BOGACKI_SHAMPINE || m == RK::RKF45));
    SV_CHECK(status, std::string(RK::Name(m)) != "unknown");
  }
  SV_CHECK(status, std::string(RK::Name(RK::RKF45 + 1)) == "unknown");
  TestOrders(status);
  TestDenominator(status);
  TestWrongTableaux(status);
  TestErrorEstimate(status);
  TestFailingStage(status);
  TestReferenceDirection(status);
  TestFloat(status);
  return status.Result();
}
