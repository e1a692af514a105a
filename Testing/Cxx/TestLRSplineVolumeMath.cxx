// SPDX-License-Identifier: BSD-3-Clause
// The element search and Bezier evaluation that vtkLRSplineVolumeMapper's
// fragment stage runs (glsl/vtkLRSplineVolumeShared.glsl, compiled as C++ in
// single precision by vtkLRSplineVolumeMath.h) against the double-precision
// CPU code (vtkLRSplineElementLocator, vtkLRSplineBezierVolume), on the flat
// arrays the mapper uploads:
// - the k-d forest (automatic, 1^3 and 8^3 blocks), the k-d tree, the octree
//   and the look-up texture return the locator's element for random points
//   element centres, corners and edge points of the real three-patch file and of generated
//   locally refined volumes (non-dyadic; dyadic for octree and texture);
//   a point may only land in another element when it lies within float
//   rounding of a face, and then in an element that touches it;
// - the Bernstein basis and the tensor-product evaluation (value and the
//   three derivatives) agree to float precision;
// - exact degree elevation (vtkLRSplineBezierVolume::ElevateDegree, used for
//   patches of lower degree) leaves every element's polynomial unchanged.
#include "LRSplineTestUtilities.h"
#include "LRSplineVolumeTestUtilities.h"
#include "SplineVizTestUtilities.h"

#include "vtkLRSplineVolumeMath.h"

#include "vtkLRSplineBezierVolume.h"
#include "vtkLRSplineElementLocator.h"
#include "vtkLRSplineField.h"

#include <cmath>
#include <iostream>
#include <random>

namespace
{
bool NearFace(const double* box, const double u[3])
{
  for (int d = 0; d < 3; ++d)
  {
    const double tol = 1e-5 * (1.0 + std::abs(u[d]));
    if (std::abs(u[d] - box[d]) < tol || std::abs(u[d] - box[d + 3]) < tol)
    {
      return true;
    }
  }
  return false;
}

bool Touches(const double* box, const double u[3])
{
  for (int d = 0; d < 3; ++d)
  {
    const double tol = 1e-5 * (1.0 + std::abs(u[d]));
    if (u[d] < box[d] - tol || u[d] > box[d + 3] + tol)
    {
      return false;
    }
  }
  return true;
}

// Check one patch with one locator type.
void CheckPatch(
  SplineVizTestStatus& status, const vtkLRSplineEvaluator& patch, const std::string& what)
{
  const vtkLRSplineElementLocator& loc = patch.GetLocator();
  vtkLRSplineBezierVolume volume = patch.GetVolume();
  volume.MakeFloatCoefficients();
  const std::vector<float> splits = loc.GetNodeSplitsFloat();
  vtkLRSplineVolumeMath::Data data;
  data.Heads = loc.GetHeads().data();
  data.NodeWords = loc.GetNodeWords().data();
  data.NodeSplits = splits.data();
  data.Octree = loc.GetOctreeNodes().data();
  data.Coefficients = volume.CoefficientsFloat.data();
  vtkLRSplineVolumeMath::SetData(&data);

  const double* dom = loc.GetDomain();
  const glm::vec3 lo(dom[0], dom[1], dom[2]), hi(dom[3], dom[4], dom[5]);
  const int* nb = loc.GetNumberOfBlocks();
  const glm::ivec3 blocks(nb[0], nb[1], nb[2]);
  const bool octree = loc.GetType() == vtkLRSplineElementLocator::OCTREE;

  std::vector<std::array<double, 3>> points;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (int i = 0; i < 4000; ++i)
  {
    points.push_back({ dom[0] + U(rng) * (dom[3] - dom[0]), dom[1] + U(rng) * (dom[4] - dom[1]),
      dom[2] + U(rng) * (dom[5] - dom[2]) });
  }
  for (vtkIdType e = 0; e < volume.GetNumberOfElements(); ++e)
  {
    const double* b = volume.GetBox(e);
    points.push_back({ 0.5 * (b[0] + b[3]), 0.5 * (b[1] + b[4]), 0.5 * (b[2] + b[5]) });
    points.push_back({ b[0], b[1], b[2] }); // a corner: faces of several elements
    points.push_back({ b[3], 0.5 * (b[1] + b[4]), b[5] });
  }

  const int* deg = volume.Degree;
  const int nc = volume.NumberOfComponents;
  const int per = volume.GetCoefficientsPerElement() * nc;
  double maxCoefficient = 0.0;
  for (double c : volume.Coefficients)
  {
    maxCoefficient = std::max(maxCoefficient, std::abs(c));
  }
  long long exact = 0, nearFace = 0, wrong = 0;
  double maxValueError = 0.0, maxGradientError = 0.0;
  for (const auto& p : points)
  {
    // The shader's arithmetic: single precision parameters.
    const glm::vec3 u(static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2]));
    const double ud[3] = { u.x, u.y, u.z };
    const vtkIdType cpu = loc.FindElement(ud);
    const int gpu = octree ? vtkLRSplineVolumeMath::lrFindOctree(u, lo, hi, 0)
                           : vtkLRSplineVolumeMath::lrFindForest(u, lo, hi, blocks, 0, 0);
    if (cpu < 0)
    {
      ++wrong;
      continue;
    }
    if (gpu == cpu)
    {
      ++exact;
    }
    else if (gpu >= 0 && NearFace(volume.GetBox(cpu), ud) && Touches(volume.GetBox(gpu), ud))
    {
      ++nearFace;
    }
    else
    {
      if (wrong < 5)
      {
        std::cerr << "ERROR: " << what << ": point (" << ud[0] << ", " << ud[1] << ", " << ud[2]
                  << "): the shader code finds element " << gpu << ", the locator " << cpu
                  << std::endl;
      }
      ++wrong;
      continue;
    }
    // Evaluate in the shader's element, in its local coordinates.
    const double* b = volume.GetBox(gpu);
    glm::vec3 s;
    double sd[3];
    for (int d = 0; d < 3; ++d)
    {
      s[d] = std::min(1.0f, std::max(0.0f, static_cast<float>((u[d] - b[d]) / (b[d + 3] - b[d]))));
      sd[d] = s[d];
    }
    std::vector<double> value(nc), dlocal(3 * nc);
    volume.EvaluateLocal(gpu, sd, value.data(), dlocal.data());
    for (int c = 0; c < nc; ++c)
    {
      glm::vec3 grad;
      const float v = vtkLRSplineVolumeMath::lrEvaluate(
        static_cast<int>(gpu * per), deg[0], deg[1], deg[2], nc, c, s, grad);
      maxValueError = std::max(maxValueError, std::abs(v - value[c]));
      for (int d = 0; d < 3; ++d)
      {
        maxGradientError = std::max(maxGradientError, std::abs(grad[d] - dlocal[3 * c + d]));
      }
    }
  }
  const double scale = std::max(maxCoefficient, 1e-30);
  std::cout << what << ": " << points.size() << " points, " << exact << " same element, "
            << nearFace << " neighbour within rounding of a face, " << wrong
            << " wrong; value error " << maxValueError / scale << ", derivative error "
            << maxGradientError / scale << " (relative to the largest coefficient)" << std::endl;
  SV_CHECK_MSG(status, wrong == 0, what + ": elements the shader code gets wrong");
  SV_CHECK_MSG(status, nearFace * 2 < static_cast<long long>(points.size()),
    what + ": too many face-rounding cases");
  SV_CHECK_MSG(status, maxValueError <= 1e-5 * scale, what + ": value error");
  // Derivatives in local coordinates grow like degree x coefficient range.
  SV_CHECK_MSG(status, maxGradientError <= 1e-4 * scale, what + ": derivative error");
  vtkLRSplineVolumeMath::SetData(nullptr);
}

void CheckField(SplineVizTestStatus& status, vtkDataObject* data, int type, const int* blocks,
  const std::string& what)
{
  vtkLRSplineField field;
  std::string error;
  if (!field.Build(data, nullptr, type, blocks, false, &error))
  {
    status.Fail(what + ": " + error, __FILE__, __LINE__);
    return;
  }
  for (int p = 0; p < field.GetNumberOfPatches(); ++p)
  {
    CheckPatch(status, field.GetPatch(p),
      what + " patch " + std::to_string(p) + " (" + vtkLRSplineElementLocator::GetTypeName(type) +
        ")");
  }
}

// A dyadic locally refined volume (uniform breaks, halving): the octree and
// the look-up texture apply.
vtkSmartPointer<vtkMultiBlockDataSet> DyadicVolume(const std::string& path)
{
  const int degree[3] = { 3, 2, 1 };
  const double focus[3] = { 0.3, 0.6, 0.45 };
  if (!lrvolume::WriteDyadicVolume(degree, focus, 4, path))
  {
    return nullptr;
  }
  vtkNew<vtkLRSplineReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  return reader->GetOutput();
}
}

int TestLRSplineVolumeMath(int, char*[])
{
  SplineVizTestStatus status;

  // The Bernstein basis.
  {
    double worst = 0.0;
    for (int n = 0; n <= 3; ++n)
    {
      for (int k = 0; k <= 20; ++k)
      {
        const float s = k / 20.0f;
        glm::vec4 b, d;
        vtkLRSplineVolumeMath::lrBernstein(n, s, b, d);
        double rb[16], rd[16];
        vtkLRSplineBezierVolume::Bernstein<double>(n, s, rb, rd);
        for (int i = 0; i <= n; ++i)
        {
          worst = std::max(worst, std::max(std::abs(b[i] - rb[i]), std::abs(d[i] - rd[i])));
        }
      }
    }
    std::cout << "Bernstein basis and derivatives, degrees 0-3: max error " << worst << std::endl;
    SV_CHECK(status, worst < 1e-5);
  }

  // Element search and evaluation on real and generated volumes.
  vtkNew<vtkLRSplineReader> reader;
  reader->SetFileName(SPLINEVIZ_EXTERNAL_DATA_DIR "/cube-3patch-refined.lr");
  reader->Update();
  const std::string dir = SPLINEVIZ_TEST_OUTPUT_DIR;
  vtkSmartPointer<vtkMultiBlockDataSet> refined =
    lrvolume::RefinedScalarVolume(dir + "/TestLRSplineVolumeMath-refined.lr", 5);
  vtkSmartPointer<vtkMultiBlockDataSet> dyadic =
    DyadicVolume(dir + "/TestLRSplineVolumeMath-dyadic.lr");
  SV_CHECK(status, refined && dyadic);
  if (!refined || !dyadic)
  {
    return status.Result();
  }
  const int one[3] = { 1, 1, 1 }, eight[3] = { 8, 8, 8 };
  CheckField(status, reader->GetOutput(), vtkLRSplineElementLocator::KD_FOREST, nullptr,
    "cube-3patch-refined.lr");
  CheckField(status, reader->GetOutput(), vtkLRSplineElementLocator::OCTREE, nullptr,
    "cube-3patch-refined.lr");
  CheckField(status, refined, vtkLRSplineElementLocator::KD_FOREST, nullptr, "refined");
  CheckField(status, refined, vtkLRSplineElementLocator::KD_FOREST, one, "refined 1^3");
  CheckField(status, refined, vtkLRSplineElementLocator::KD_FOREST, eight, "refined 8^3");
  CheckField(status, refined, vtkLRSplineElementLocator::KD_TREE, nullptr, "refined");
  CheckField(status, dyadic, vtkLRSplineElementLocator::KD_FOREST, nullptr, "dyadic");
  CheckField(status, dyadic, vtkLRSplineElementLocator::OCTREE, nullptr, "dyadic");
  CheckField(status, dyadic, vtkLRSplineElementLocator::TEXTURE, nullptr, "dyadic");

  // Exact degree elevation.
  {
    vtkLRSplineField field;
    std::string error;
    SV_CHECK(status,
      field.Build(dyadic, nullptr, vtkLRSplineElementLocator::KD_FOREST, nullptr, false, &error));
    const vtkLRSplineBezierVolume& original = field.GetPatch(0).GetVolume();
    vtkLRSplineBezierVolume raised = original;
    const int lower[3] = { 2, 2, 1 };
    SV_CHECK_MSG(status, !raised.ElevateDegree(lower), "elevation to a lower degree must fail");
    const int target[3] = { 3, 3, 3 };
    SV_CHECK(status, raised.ElevateDegree(target));
    SV_CHECK(status, raised.Degree[0] == 3 && raised.Degree[1] == 3 && raised.Degree[2] == 3);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    double worst = 0.0;
    const int nc = original.NumberOfComponents;
    std::vector<double> a(nc), da(3 * nc), b(nc), db(3 * nc);
    for (vtkIdType e = 0; e < original.GetNumberOfElements(); e += 7)
    {
      for (int k = 0; k < 10; ++k)
      {
        const double s[3] = { U(rng), U(rng), U(rng) };
        original.EvaluateLocal(e, s, a.data(), da.data());
        raised.EvaluateLocal(e, s, b.data(), db.data());
        for (int c = 0; c < nc; ++c)
        {
          worst = std::max(worst, std::abs(a[c] - b[c]));
        }
        for (int c = 0; c < 3 * nc; ++c)
        {
          worst = std::max(worst, std::abs(da[c] - db[c]));
        }
      }
    }
    std::cout << "degree elevation (3, 2, 1) -> (3, 3, 3): max change of values and derivatives "
              << worst << std::endl;
    SV_CHECK(status, worst < 1e-12);
  }
  return status.Result();
}
