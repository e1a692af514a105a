// SPDX-License-Identifier: BSD-3-Clause
// Hostile sizes on the GPU: data larger than the GPU's buffer
// limits must give one clear error (vtkErrorMacro, naming the limit) and
// draw nothing, never crash or draw stale or partial data. The limit is
// forced small with SPLINEVIZ_GPU_BUFFER_LIMIT (texels per GPU buffer, or
// glyphs per draw) so that the path runs with small data; the real limit
// (GL_MAX_TEXTURE_BUFFER_SIZE, GL_OUT_OF_MEMORY) goes through the same code.
// For each of vtkRayCastTubeMapper, vtkTessellatedTubeMapper,
// vtkStylizedLineMapper and vtkSuperquadricGlyphMapper:
//  1. over the limit: an error naming SPLINEVIZ_GPU_BUFFER_LIMIT, no pixel
//     drawn; a second frame: no further error, still nothing drawn (for the
//     tube mappers: more than the 4 buffers an array may be split into);
//  2. data under the limit: drawn, no error (the limit is per buffer);
//  3. negative control: the limit lifted, the same large data is drawn, so
//     the limit alone is what kept it off the screen.
// For the three tube mappers also:
//  4. pages: data over one buffer's limit but within 4 buffers is split into
//     pages (vtkSplineVizGPUBuffer) and drawn exactly as without a limit:
//     the same colored picture to the byte, no error; negative control: one
//     node moved by a hundredth of a tube's radius changes that picture, so
//     the comparison would see a node read from the wrong page.
#include "vtkRayCastTubeMapper.h"
#include "vtkSplineTubeCore.h"
#include "vtkStylizedLineMapper.h"
#include "vtkSuperquadricGlyphMapper.h"
#include "vtkTessellatedTubeMapper.h"

#include "SplineVizTestUtilities.h"
#include "SuperquadricGlyphTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTestErrorObserver.h"

#include <array>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

namespace
{
constexpr int W = 200;
constexpr int H = 200;
const char* const LimitVariable = "SPLINEVIZ_GPU_BUFFER_LIMIT";

/// `lines` polylines of `points` points across [-1, 1]^2, radius 0.03.
vtkSmartPointer<vtkPolyData> Lines(int lines, int points)
{
  vtkNew<vtkPoints> pts;
  vtkNew<vtkDoubleArray> radius;
  radius->SetName("Radius");
  vtkNew<vtkDoubleArray> value; // colors: the per-node colors are paged too
  value->SetName("Value");
  vtkNew<vtkCellArray> cells;
  for (int l = 0; l < lines; ++l)
  {
    cells->InsertNextCell(points);
    const double y = lines > 1 ? -0.9 + 1.8 * l / (lines - 1) : 0.0;
    for (int i = 0; i < points; ++i)
    {
      const double x = -0.9 + 1.8 * i / (points - 1);
      cells->InsertCellPoint(pts->InsertNextPoint(x, y + 0.02 * std::sin(7.0 * x), 0.0));
      radius->InsertNextValue(0.03);
      value->InsertNextValue(std::sin(3.0 * x + 0.7 * l));
    }
  }
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->SetPoints(pts);
  pd->SetLines(cells);
  pd->GetPointData()->AddArray(radius);
  pd->GetPointData()->SetScalars(value);
  return pd;
}

/// Glyphs of `n` x `n` prolate tensors on a unit-spaced image.
vtkSmartPointer<vtkImageData> Glyphs(int n)
{
  std::vector<std::array<double, 6>> tensors(static_cast<std::size_t>(n) * n);
  for (auto& t : tensors)
  {
    t = { 1.0, 0.4, 0.3, 0.0, 0.0, 0.0 };
  }
  return sqtest::TensorImage(tensors, n);
}

struct Frame
{
  int Covered = 0;
  std::string Errors;
  std::vector<unsigned char> Pixels; ///< RGB
};

/// Pixels whose color differs between two frames.
int Differing(const Frame& a, const Frame& b)
{
  int n = 0;
  for (size_t i = 0; i + 2 < a.Pixels.size() && i + 2 < b.Pixels.size(); i += 3)
  {
    n += a.Pixels[i] != b.Pixels[i] || a.Pixels[i + 1] != b.Pixels[i + 1] ||
      a.Pixels[i + 2] != b.Pixels[i + 2];
  }
  return n;
}

struct Scene
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkActor> Actor;
  vtkNew<vtkTest::ErrorObserver> Observer;

  explicit Scene(vtkMapper* mapper)
  {
    this->Window->SetSize(W, H);
    this->Window->SetMultiSamples(0);
    this->Window->SetOffScreenRendering(1);
    this->Window->AddRenderer(this->Renderer);
    this->Renderer->SetBackground(0, 0, 0);
    this->Actor->SetMapper(mapper);
    this->Renderer->AddActor(this->Actor);
    mapper->AddObserver(vtkCommand::ErrorEvent, this->Observer);
    mapper->AddObserver(vtkCommand::WarningEvent, this->Observer);
  }

  Frame Render()
  {
    this->Observer->Clear();
    this->Window->Render();
    Frame f;
    unsigned char* p = this->Window->GetPixelData(0, 0, W - 1, H - 1, 0);
    for (int i = 0; i < W * H; ++i)
    {
      f.Covered += (p[3 * i] | p[3 * i + 1] | p[3 * i + 2]) != 0;
    }
    f.Pixels.assign(p, p + 3 * W * H);
    delete[] p;
    f.Errors = this->Observer->GetErrorMessage() + this->Observer->GetWarningMessage();
    return f;
  }
};

/// The three steps of the file comment for one mapper; `setLarge` and
/// `setSmall` give it its input and point the camera at it.
void CheckMapper(SplineVizTestStatus& status, const std::string& what, Scene& scene,
  const std::function<void()>& setLarge, const std::function<void()>& setSmall)
{
  setenv(LimitVariable, "100", 1);
  setLarge();
  Frame f = scene.Render();
  SV_CHECK_MSG(status, f.Errors.find(LimitVariable) != std::string::npos,
    what << ": over the limit, the error \"" << f.Errors << "\" does not name the limit");
  SV_CHECK_MSG(
    status, f.Covered == 0, what << ": over the limit, " << f.Covered << " pixels drawn");
  std::cout << what << ": " << f.Errors.substr(0, f.Errors.find('\n')) << std::endl;
  f = scene.Render();
  SV_CHECK_MSG(status, f.Errors.empty(), what << ": the error came again: " << f.Errors);
  SV_CHECK_MSG(status, f.Covered == 0, what << ": second frame, " << f.Covered << " pixels drawn");

  setSmall();
  f = scene.Render();
  SV_CHECK_MSG(status, f.Errors.empty(), what << ": under the limit, errors: " << f.Errors);
  SV_CHECK_MSG(
    status, f.Covered > 100, what << ": under the limit, only " << f.Covered << " pixels");
  const int small = f.Covered;

  unsetenv(LimitVariable);
  setLarge();
  f = scene.Render();
  SV_CHECK_MSG(status, f.Errors.empty(), what << ": without the limit, errors: " << f.Errors);
  SV_CHECK_MSG(status, f.Covered > small,
    what << ": without the limit the large data covers " << f.Covered << " pixels (small: " << small
         << ")");
  std::cout << what << ": small data " << small << " pixels, large data " << f.Covered
            << " pixels without the limit" << std::endl;
}

void CheckTubeMapper(
  SplineVizTestStatus& status, const std::string& what, vtkSplineTubeMapper* mapper)
{
  Scene scene(mapper);
  mapper->SetRadiusArray("Radius");
  mapper->GetTubeCore()->AddObserver(vtkCommand::ErrorEvent, scene.Observer);
  vtkSmartPointer<vtkPolyData> large = Lines(40, 12); // 480 nodes: over 100 texels
  vtkSmartPointer<vtkPolyData> small = Lines(2, 8);   // 16 nodes
  auto look = [&]()
  {
    vtkCamera* camera = scene.Renderer->GetActiveCamera();
    camera->SetFocalPoint(0, 0, 0);
    camera->SetPosition(0, 0, 5);
    camera->SetViewUp(0, 1, 0);
    camera->SetClippingRange(1, 10);
  };
  CheckMapper(
    status, what, scene,
    [&]()
    {
      mapper->SetInputData(large);
      look();
    },
    [&]()
    {
      mapper->SetInputData(small);
      look();
    });

  // 4. Pages: 480 nodes in buffers of at most 128 texels: 4 pages. Each
  // render gets a new copy of the data, so that it is uploaded again.
  auto draw = [&](vtkPolyData* data, const char* limit)
  {
    if (limit)
    {
      setenv(LimitVariable, limit, 1);
    }
    else
    {
      unsetenv(LimitVariable);
    }
    vtkNew<vtkPolyData> copy;
    copy->DeepCopy(data);
    mapper->SetInputData(copy);
    look();
    Frame f = scene.Render();
    unsetenv(LimitVariable);
    return f;
  };
  const Frame whole = draw(large, nullptr);
  const Frame paged = draw(large, "128");
  SV_CHECK_MSG(status, paged.Errors.empty(), what << ": in 4 pages, errors: " << paged.Errors);
  SV_CHECK_MSG(status, whole.Covered > 2000 && paged.Covered == whole.Covered,
    what << ": in 4 pages " << paged.Covered << " pixels drawn, in one buffer " << whole.Covered);
  const int differing = Differing(whole, paged);
  SV_CHECK_MSG(status, differing == 0,
    what << ": in 4 pages " << differing << " pixels differ from the picture in one buffer");
  const Frame two = draw(large, "300"); // pages of 256 texels (a power of two): 2
  SV_CHECK_MSG(status, two.Errors.empty() && Differing(whole, two) == 0,
    what << ": in pages of 256 texels " << Differing(whole, two)
         << " pixels differ from the picture in one buffer");
  // Negative control: one node of the last page moved by a hundredth of the radius.
  vtkNew<vtkPolyData> moved;
  moved->DeepCopy(large);
  double p[3];
  moved->GetPoints()->GetPoint(400, p);
  moved->GetPoints()->SetPoint(400, p[0], p[1] + 0.0003, p[2]);
  const int control = Differing(whole, draw(moved, nullptr));
  SV_CHECK_MSG(status, control > 0,
    what << ": negative control: a node moved by 0.01 radius changed no pixel");
  std::cout << what << ": 4 pages of 128 texels and 2 of 256 draw the same " << whole.Covered
            << " pixels as one buffer; a moved node changes " << control << std::endl;
}
}

int TestSplineVizGPULimits(int, char*[])
{
  SplineVizTestStatus status;
  {
    vtkNew<vtkRayCastTubeMapper> mapper;
    CheckTubeMapper(status, "vtkRayCastTubeMapper", mapper);
  }
  {
    vtkNew<vtkTessellatedTubeMapper> mapper;
    CheckTubeMapper(status, "vtkTessellatedTubeMapper", mapper);
  }
  {
    vtkNew<vtkStylizedLineMapper> mapper;
    CheckTubeMapper(status, "vtkStylizedLineMapper", mapper);
  }
  {
    vtkNew<vtkSuperquadricGlyphMapper> mapper;
    mapper->SetScaleFactor(0.42);
    Scene scene(mapper);
    auto look = [&](int n)
    {
      vtkCamera* camera = scene.Renderer->GetActiveCamera();
      camera->SetFocalPoint(0.5 * (n - 1), 0.5 * (n - 1), 0);
      camera->SetPosition(0.5 * (n - 1), 0.5 * (n - 1), 2.2 * n);
      camera->SetViewUp(0, 1, 0);
      camera->SetClippingRange(0.5 * n, 4.0 * n);
    };
    CheckMapper(
      status, "vtkSuperquadricGlyphMapper", scene,
      [&]()
      {
        mapper->SetInputData(Glyphs(12)); // 144 glyphs: over 100
        look(12);
      },
      [&]()
      {
        mapper->SetInputData(Glyphs(6)); // 36 glyphs, a quarter of the view
        look(12);
      });
  }
  return status.Result();
}
