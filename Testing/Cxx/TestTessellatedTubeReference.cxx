// SPDX-License-Identifier: BSD-3-Clause
// vtkTessellatedTubeMapper against an independent reference rendering: the
// same tubes built by vtkTubeFilter (64 sides, flat caps) around the spline
// centerline resampled 64 times per segment by this test's own Hermite code,
// shaded with this test's own point normals (area-weighted averages of the
// triangles' normals: vtkPolyDataNormals changed its weighting in VTK 9.3,
// which moved the reference, not the mapper, by 4-5 gray levels on average).
//
// For several views (close-up and middle distance in perspective, a far view
// where the coarse levels of detail are used, a parallel projection):
//  - coverage: the pixels covered agree to within one pixel (Chebyshev
//    distance; at most a handful of stray pixels);
//  - shading: inside the common coverage (eroded by 2 pixels) the diffusely
//    lit gray levels agree on average and in their 99th percentile.
// In the far view the thin tubes use the coarsest levels of detail (a few
// vertices per ring, their normals interpolated): there the shading is only
// checked on average.
// Negative controls, which must fail the same checks:
//  - the base mesh only (refinement skipped: levels 1, no level of detail),
//    in the close-up;
//  - mis-oriented frames: the node vectors left in model coordinates and the
//    interpolated vector not re-projected onto the cross-section plane (the
//    cross-sections tilt and shrink), in the whole-scene view. (Without the
//    re-projection alone the good frames stay nearly orthogonal to the
//    tangent: the test prints that case for information.)
//  - the orthogonal vector chosen per vertex instead of propagated (frames
//    not rotation-minimizing; twisted rings as in Salm Fig. 6), likewise.
// SPLINEVIZ_TEST_IMAGES=<dir> writes the renderings as PNG files.
#include "vtkTessellatedTubeMapper.h"

#include "SplineTubeTestScenes.h"
#include "SplineVizTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkObjectFactory.h"
#include "vtkPNGWriter.h"
#include "vtkPolyDataMapper.h"
#include "vtkPointData.h"
#include "vtkTriangleFilter.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTubeFilter.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <string>

namespace
{
/// A mapper whose tessellation stages compute the orthogonal vector wrongly:
/// `Replacement` replaces its interpolation in the evaluation stage; with
/// `ModelFrames` the node vectors are also left in model coordinates (not
/// rotated into view coordinates with the positions).
class BrokenFramesMapper : public vtkTessellatedTubeMapper
{
public:
  static BrokenFramesMapper* New();
  vtkTypeMacro(BrokenFramesMapper, vtkTessellatedTubeMapper);
  std::string Replacement;
  bool ModelFrames = false;

protected:
  static void Break(std::string& source, const std::string& what, const std::string& with)
  {
    if (!vtkShaderProgram::Substitute(source, what, with))
    {
      std::cerr << "ERROR: the shader code to break was not found: " << what << std::endl;
      std::exit(EXIT_FAILURE);
    }
  }
  std::string Frames(std::string source)
  {
    if (this->ModelFrames)
    {
      Break(source, "return normalize(mat3(tubeMCVC) * f);", "return f;");
    }
    return source;
  }
  std::string GetTessellationControlShaderSource() override
  {
    return this->Frames(this->Superclass::GetTessellationControlShaderSource());
  }
  std::string GetTessellationEvaluationShaderSource() override
  {
    std::string source = this->Frames(this->Superclass::GetTessellationEvaluationShaderSource());
    Break(source, "vec3 n = svInterpolateFrame(f0, f1, t, d);", this->Replacement);
    return source;
  }
};
vtkStandardNewMacro(BrokenFramesMapper);

const unsigned char Background[3] = { 0, 0, 0 };
const int Size = 400;

struct View
{
  std::string Name;
  std::function<void(vtkCamera*, vtkRenderer*)> Setup;
};

/// The tubes as triangles, each wound outward (as vtkTubeFilter's own radial
/// and cap normals point), with point normals averaged over the triangles
/// around each point, weighted by their areas.
vtkSmartPointer<vtkPolyData> WithAreaWeightedNormals(vtkPolyData* tubes)
{
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(tubes);
  triangles->PassLinesOff();
  triangles->PassVertsOff();
  triangles->Update();
  vtkPolyData* mesh = triangles->GetOutput();
  vtkDataArray* outward = mesh->GetPointData()->GetNormals();
  vtkPoints* points = mesh->GetPoints();
  std::vector<std::array<double, 3>> sums(mesh->GetNumberOfPoints(), { 0.0, 0.0, 0.0 });
  vtkNew<vtkCellArray> oriented;
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  auto cells = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    cells->GetCurrentCell(n, ids);
    if (n != 3)
    {
      continue;
    }
    double p[3][3];
    for (int k = 0; k < 3; ++k)
    {
      points->GetPoint(ids[k], p[k]);
    }
    // Twice the area times the unit normal, by the winding.
    const double a[3] = { p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2] };
    const double b[3] = { p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2] };
    double c[3] = { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
      a[0] * b[1] - a[1] * b[0] };
    double facing = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      double o[3];
      outward->GetTuple(ids[k], o);
      facing += c[0] * o[0] + c[1] * o[1] + c[2] * o[2];
    }
    vtkIdType tri[3] = { ids[0], ids[1], ids[2] };
    if (facing < 0.0)
    {
      std::swap(tri[1], tri[2]);
      for (double& v : c)
      {
        v = -v;
      }
    }
    oriented->InsertNextCell(3, tri);
    for (vtkIdType id : tri)
    {
      for (int k = 0; k < 3; ++k)
      {
        sums[id][k] += c[k];
      }
    }
  }
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(mesh->GetNumberOfPoints());
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    const auto& v = sums[i];
    const double len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    const double scale = len > 0.0 ? 1.0 / len : 0.0;
    normals->SetTuple3(i, v[0] * scale, v[1] * scale, v[2] * scale);
  }
  auto result = vtkSmartPointer<vtkPolyData>::New();
  result->SetPoints(points);
  result->SetPolys(oriented);
  result->GetPointData()->SetNormals(normals);
  return result;
}

void Save(const SplineTubeTest::Image& image, const std::string& name)
{
  const char* dir = std::getenv("SPLINEVIZ_TEST_IMAGES");
  if (!dir)
  {
    return;
  }
  vtkNew<vtkImageData> data;
  data->SetDimensions(image.Width, image.Height, 1);
  data->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  std::copy(
    image.RGB.begin(), image.RGB.end(), static_cast<unsigned char*>(data->GetScalarPointer()));
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(data);
  writer->SetFileName((std::string(dir) + "/" + name + ".png").c_str());
  writer->Write();
}

/// One window for every rendering of the test.
vtkRenderWindow* Window()
{
  static vtkSmartPointer<vtkRenderWindow> window;
  if (!window)
  {
    window = vtkSmartPointer<vtkRenderWindow>::New();
    window->SetOffScreenRendering(1);
    window->SetMultiSamples(0);
    window->SetSize(Size, Size);
  }
  return window;
}

/// Render `mapper` (coverage: flat white; shading: diffuse gray) in `view`.
SplineTubeTest::Image Render(vtkMapper* mapper, const View& view, bool shaded)
{
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(1.0, 1.0, 1.0);
  if (shaded)
  {
    actor->GetProperty()->SetColor(0.8, 0.8, 0.8);
    actor->GetProperty()->SetAmbient(0.0);
    actor->GetProperty()->SetDiffuse(1.0);
    actor->GetProperty()->SetSpecular(0.0);
  }
  else
  {
    actor->GetProperty()->SetAmbient(1.0);
    actor->GetProperty()->SetDiffuse(0.0);
    actor->GetProperty()->SetSpecular(0.0);
  }
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(0.0, 0.0, 0.0);
  vtkRenderWindow* window = Window();
  window->AddRenderer(renderer);
  view.Setup(renderer->GetActiveCamera(), renderer);
  renderer->ResetCameraClippingRange(-4, 4, -4, 4, -4, 4);
  window->Render();
  SplineTubeTest::Image image = SplineTubeTest::Grab(window);
  window->RemoveRenderer(renderer);
  return image;
}

struct Comparison
{
  SplineTubeTest::Coverage Coverage;
  double MeanShade = 0.0;
  double Shade99 = 0.0;
};

Comparison Compare(const SplineTubeTest::Image& refFlat, const SplineTubeTest::Image& refShaded,
  const SplineTubeTest::Image& flat, const SplineTubeTest::Image& shaded)
{
  Comparison c;
  const auto reference = SplineTubeTest::Mask(refFlat, Background);
  const auto test = SplineTubeTest::Mask(flat, Background);
  c.Coverage = SplineTubeTest::CompareCoverage(reference, test, Size, Size, 1);
  // Shading inside both coverages, away from the silhouettes.
  std::vector<unsigned char> both(reference.size());
  for (size_t i = 0; i < both.size(); ++i)
  {
    both[i] = reference[i] && test[i];
  }
  const auto inner = SplineTubeTest::Morph(both, Size, Size, 2, false);
  std::vector<double> differences;
  for (int y = 0; y < Size; ++y)
  {
    for (int x = 0; x < Size; ++x)
    {
      if (inner[y * Size + x])
      {
        differences.push_back(
          std::abs(static_cast<double>(refShaded.At(x, y)[0]) - shaded.At(x, y)[0]));
      }
    }
  }
  if (!differences.empty())
  {
    double sum = 0.0;
    for (double d : differences)
    {
      sum += d;
    }
    c.MeanShade = sum / differences.size();
    std::sort(differences.begin(), differences.end());
    c.Shade99 = differences[static_cast<size_t>(0.99 * (differences.size() - 1))];
  }
  return c;
}

// Acceptance: coverage to within a pixel (a few stray pixels allowed),
// shading within a few gray levels (coarse levels of detail: on average).
const long MaxStrayPixels = 8;
const double MaxMeanShade = 3.0;
const double MaxShade99 = 16.0;
const double MaxCoarseMeanShade = 6.0;

bool Accepted(const Comparison& c, bool coarse = false)
{
  return c.Coverage.Extra + c.Coverage.Missing <= MaxStrayPixels &&
    (coarse ? c.MeanShade <= MaxCoarseMeanShade
            : c.MeanShade <= MaxMeanShade && c.Shade99 <= MaxShade99);
}

void Report(const std::string& what, const Comparison& c, bool coarse = false)
{
  std::cout << what << ": reference " << c.Coverage.Reference << " px, extra " << c.Coverage.Extra
            << ", missing " << c.Coverage.Missing << "; shading mean " << c.MeanShade << ", 99% "
            << c.Shade99 << (Accepted(c, coarse) ? "  (agrees)" : "  (DIFFERS)") << std::endl;
}
}

int TestTessellatedTubeReference(int, char*[])
{
  SplineVizTestStatus status;
  const std::vector<SplineTubeTest::Line> lines = SplineTubeTest::TestLines();
  vtkSmartPointer<vtkPolyData> input = SplineTubeTest::MakePolyData(lines);

  // The reference: vtkTubeFilter around the independently resampled splines.
  vtkSmartPointer<vtkPolyData> dense =
    SplineTubeTest::MakePolyData(SplineTubeTest::ResampleSplines(lines, 64));
  dense->GetPointData()->SetActiveScalars("Radius");
  vtkNew<vtkTubeFilter> tubes;
  tubes->SetInputData(dense);
  tubes->SetNumberOfSides(64);
  tubes->SetVaryRadiusToVaryRadiusByAbsoluteScalar();
  tubes->CappingOn();
  tubes->Update();
  vtkNew<vtkPolyDataMapper> reference;
  reference->SetInputData(WithAreaWeightedNormals(tubes->GetOutput()));
  reference->ScalarVisibilityOff();

  vtkNew<vtkTessellatedTubeMapper> mapper;
  mapper->SetInputData(input);
  mapper->SetRadiusArray("Radius");
  mapper->ScalarVisibilityOff();

  std::vector<View> views = {
    { "close-up",
      [](vtkCamera* cam, vtkRenderer*)
      {
        cam->SetFocalPoint(0.5, 0.6, -0.6);
        cam->SetPosition(2.6, 2.2, 0.4);
        cam->SetViewUp(0, 0, 1);
        cam->SetViewAngle(30);
      } },
    { "whole scene",
      [](vtkCamera* cam, vtkRenderer*)
      {
        cam->SetFocalPoint(0.0, 0.0, 0.4);
        cam->SetPosition(2.0, -7.5, 4.4);
        cam->SetViewUp(0, 0, 1);
        cam->SetViewAngle(40);
      } },
    { "far",
      [](vtkCamera* cam, vtkRenderer*)
      {
        cam->SetFocalPoint(0.0, 0.0, 0.4);
        cam->SetPosition(4.5, -16.5, 10.2);
        cam->SetViewUp(0, 0, 1);
        cam->SetViewAngle(40);
      } },
    { "parallel",
      [](vtkCamera* cam, vtkRenderer*)
      {
        cam->ParallelProjectionOn();
        cam->SetParallelScale(1.2);
        cam->SetFocalPoint(0.0, 0.3, 0.0);
        cam->SetPosition(0.0, 0.3, 10.0);
        cam->SetViewUp(0, 1, 0);
      } },
  };

  std::vector<SplineTubeTest::Image> refFlat;
  std::vector<SplineTubeTest::Image> refShaded;
  for (const View& view : views)
  {
    refFlat.push_back(Render(reference, view, false));
    refShaded.push_back(Render(reference, view, true));
    Save(refShaded.back(), "reference-" + view.Name);
  }

  // 1. The mapper agrees with the reference in every view.
  for (size_t v = 0; v < views.size(); ++v)
  {
    const SplineTubeTest::Image flat = Render(mapper, views[v], false);
    const SplineTubeTest::Image shaded = Render(mapper, views[v], true);
    Save(shaded, "tessellated-" + views[v].Name);
    const bool coarse = views[v].Name == "far";
    const Comparison c = Compare(refFlat[v], refShaded[v], flat, shaded);
    Report("tessellated, " + views[v].Name, c, coarse);
    std::cout << "  levels of detail: " << mapper->GetLevelOfDetailSummary() << std::endl;
    SV_CHECK_MSG(status, c.Coverage.Reference > 2000, "the reference covers too little");
    SV_CHECK_MSG(
      status, Accepted(c, coarse), views[v].Name << " view does not agree with the reference");
  }

  // 2. Negative controls in the close-up: each must be caught.
  {
    vtkNew<vtkTessellatedTubeMapper> baseOnly;
    baseOnly->SetInputData(input);
    baseOnly->SetRadiusArray("Radius");
    baseOnly->ScalarVisibilityOff();
    baseOnly->LevelOfDetailOff();
    baseOnly->SetMaxTessellationLevel(1);
    baseOnly->SetMaxSilhouetteTessellationLevel(1);
    const Comparison c = Compare(refFlat[0], refShaded[0], Render(baseOnly, views[0], false),
      Render(baseOnly, views[0], true));
    Report("base mesh only (must differ), close-up", c);
    SV_CHECK_MSG(status, !Accepted(c), "skipping the refinement went unnoticed");
  }
  struct Broken
  {
    std::string Name;
    std::string Replacement;
    bool ModelFrames;
    bool MustDiffer;
  };
  const Broken brokenFrames[] = {
    { "in model coordinates, not re-projected", "vec3 n = normalize((1.0 - t) * f0 + t * f1);",
      true, true },
    { "not propagated", "vec3 n = svAnyOrthogonal(tangent);", false, true },
    { "not re-projected", "vec3 n = normalize((1.0 - t) * f0 + t * f1);", false, false },
  };
  for (const Broken& broken : brokenFrames)
  {
    vtkNew<BrokenFramesMapper> wrong;
    wrong->Replacement = broken.Replacement;
    wrong->ModelFrames = broken.ModelFrames;
    wrong->SetInputData(input);
    wrong->SetRadiusArray("Radius");
    wrong->ScalarVisibilityOff();
    const SplineTubeTest::Image shaded = Render(wrong, views[1], true);
    Save(shaded, "frames-" + broken.Name);
    const Comparison c = Compare(refFlat[1], refShaded[1], Render(wrong, views[1], false), shaded);
    Report("frames " + broken.Name + (broken.MustDiffer ? " (must differ)" : " (information)") +
        ", whole scene",
      c);
    if (broken.MustDiffer)
    {
      SV_CHECK_MSG(status, !Accepted(c), "frames " << broken.Name << " went unnoticed");
    }
  }
  Window()->Finalize();
  return status.Result();
}
