// SPDX-License-Identifier: BSD-3-Clause
// Benchmark of direct volume rendering of LR-spline volumes (Fuchs et al.
// §4): vtkLRSplineVolumeMapper against VTK's way
// (vtkLRSplineResampleToImage, the "LR-Spline Resample To Image" filter, to
// 128^3, 256^3 and 512^3, then vtkSmartVolumeMapper with its own vector mode
// for the magnitude), side by side in one process, on
//  - the real external file Testing/Data/External/cube-3patch-refined.lr
//    (three patches, the field's magnitude),
//  - generated quadratic LR volumes at Fuchs' sizes (LRSplineBenchmarkVolumes.h;
//    cached as .lr files in --cache, so reruns only read them):
//    refined-5k (non-dyadic knots, 6 levels at 2 foci: only the k-d
//    structures apply), refined-30k (dyadic, 8 levels at 10 foci, 256x
//    between the largest and the smallest element side: the strongly refined
//    one, like Fuchs' wind case) and refined-250k (dyadic, 5 levels at 190
//    foci; the look-up texture applies),
//  - a real scan: DIPY's aniso_vox.nii.gz (python3-dipy) fitted in this run
//    by vtkLRSplineImageFitter (quadratic, 5 % of the range at every voxel),
//  - any .lr file given with --volume.
// Measured, at 640x360 and 1280x720 (offscreen, multisampling off):
//  - per element search structure (at the first window size; at the others
//    the mapper's default only, unless --all-structures-every-size)
//    (Fuchs' Figs. 4-6 tables: texture, octree,
//    k-d tree = forest 1^3, k-d forest 8^3, 64^3, 512^3 and the mapper's
//    default), with the depth statistics of vtkLRSplineElementLocator:
//    time to first frame (data in memory -> first finished frame: element
//    data and search structure built and uploaded, shaders, the frame;
//    reading the file excluded), median frame time over a rotating camera
//    (each frame finished), without and with shading, GPU bytes;
//  - samples per ray (CountSamples) and image error of adaptive steps (Eq. 4,
//    StepScale 4 ... 0.5) and of uniform steps (1 ... 32 times the smallest
//    element's adaptive step): the samples each needs at equal error;
//  - VTK's way: resampling time, time to first frame (resampling included),
//    frame time, GPU bytes (the 3D texture), image error: a curve of error
//    against cost, with our point on it;
//  - the image error of every method is the RMS difference (8-bit units per
//    channel) against the CPU reference of LRSplineVolumeTestUtilities.h
//    (exact evaluation in double precision, uniform steps half the mapper's
//    finest adaptive step, the transfer functions evaluated directly),
//    computed once per volume and view at --error-size (the reference is too
//    slow at full size); the reference's own error is estimated as its
//    difference to the same rendering at twice the step;
//  - the targets, and whether they are met.
//
//   BenchmarkLRSplineVolume [--quick] [--volumes external,refined-5k,...]
//       [--volume file.lr] [--sizes 640x360,1280x720] [--help] ...
#include "BenchmarkCommon.h"
#include "LRSplineBenchmarkVolumes.h"
#include "LRSplineVolumeTestUtilities.h"

#include "vtkLRSplineElementLocator.h"
#include "vtkLRSplineField.h"
#include "vtkLRSplineImageFitter.h"
#include "vtkLRSplineReader.h"
#include "vtkLRSplineResampleToImage.h"
#include "vtkLRSplineVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkFramebufferPass.h"
#include "vtkImageData.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNIFTIImageReader.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkPointData.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkSmartVolumeMapper.h"
#include "vtkTextureObject.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace
{
using splineviz_benchmark::Now;
using splineviz_benchmark::Split;

const double Background[3] = { 26.0 / 255.0, 26.0 / 255.0, 31.0 / 255.0 };

double Median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n == 0 ? 0.0 : (n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]));
}

/// Wall-clock and process CPU seconds (all threads: llvmpipe's, vtkSMPTools';
/// less disturbed than wall time by other jobs on a shared machine).
struct Cost
{
  double Wall = 0.0, CPU = 0.0;
};

struct Stopwatch
{
  double Wall = Now(), CPU = splineviz_benchmark::CPUTime();
  Cost Elapsed() const
  {
    return { Now() - this->Wall, splineviz_benchmark::CPUTime() - this->CPU };
  }
};

Cost operator+(const Cost& a, const Cost& b)
{
  return { a.Wall + b.Wall, a.CPU + b.CPU };
}

/// The load average of the machine (other jobs), from /proc/loadavg.
double LoadAverage()
{
  std::ifstream in("/proc/loadavg");
  double load = -1.0;
  in >> load;
  return load;
}

double MB(double bytes)
{
  return bytes / 1048576.0;
}

/// Bytes the kernel says can still be allocated (MemAvailable), or 0.
double AvailableMemory()
{
  std::ifstream in("/proc/meminfo");
  std::string key;
  double value = 0.0;
  std::string unit;
  while (in >> key >> value >> unit)
  {
    if (key == "MemAvailable:")
    {
      return value * 1024.0;
    }
  }
  return 0.0;
}

//------------------------------------------------------------------------------
// Volumes.
struct Volume
{
  std::string Name, Description;
  vtkSmartPointer<vtkDataObject> Data;
  std::unique_ptr<vtkLRSplineField> Field; // for the reference and the statistics
  double Bounds[6] = { 0, 1, 0, 1, 0, 1 };
  double Range[2] = { 0, 1 };
  double Unit = 0.1;
  double MinSide = 0, MaxSide = 0; // element sides, data units
  int Degree = 2;
  int Degrees[3] = { 2, 2, 2 }; // per direction, the largest over the patches
  int Components = 1;
  vtkIdType Elements = 0;
  bool Dyadic = false;
  bool StronglyRefined = false;
  std::vector<std::array<double, 3>> Foci; // generated volumes: where the finest detail is
  double ReadSeconds = 0.0;
  std::string Source;              // where the spline comes from (the fitted scan: the fit)
  double DataRange[2] = { 0, -1 }; // the fitted scan's voxel range (else unset)

  /// The finest adaptive step (Eq. 4), data units.
  double FinestStep() const { return this->MinSide / (1 << this->Degree); }
};

bool Describe(Volume& v)
{
  v.Field = std::make_unique<vtkLRSplineField>();
  std::string error;
  if (!v.Field->Build(
        v.Data, nullptr, vtkLRSplineElementLocator::KD_FOREST, nullptr, false, &error))
  {
    std::fprintf(stderr, "ERROR: %s: %s\n", v.Name.c_str(), error.c_str());
    return false;
  }
  v.Field->GetBounds(v.Bounds);
  v.Elements = v.Field->GetNumberOfElements();
  v.Degree = v.Field->GetMaximumDegree();
  for (int p = 0; p < v.Field->GetNumberOfPatches(); ++p)
  {
    for (int d = 0; d < 3; ++d)
    {
      v.Degrees[d] = p == 0 ? v.Field->GetPatch(p).GetVolume().Degree[d]
                            : std::max(v.Degrees[d], v.Field->GetPatch(p).GetVolume().Degree[d]);
    }
  }
  v.Components = v.Field->GetNumberOfComponents();
  v.MinSide = lrvolume::MinimumElementSide(*v.Field);
  v.MaxSide = 0.0;
  v.Dyadic = true;
  std::vector<double> magnitudes;
  for (int p = 0; p < v.Field->GetNumberOfPatches(); ++p)
  {
    const vtkLRSplineEvaluator& patch = v.Field->GetPatch(p);
    for (vtkIdType e = 0; e < patch.GetNumberOfElements(); ++e)
    {
      // The longest side of element e (physical units; the columns of
      // the patch's affine map scale the parameter sides).
      const double* b = patch.GetVolume().GetBox(e);
      const double* A = patch.GetMatrix();
      for (int k = 0; k < 3; ++k)
      {
        const double column = std::sqrt(A[k] * A[k] + A[3 + k] * A[3 + k] + A[6 + k] * A[6 + k]);
        v.MaxSide = std::max(v.MaxSide, (b[k + 3] - b[k]) * column);
      }
    }
    int levels[3];
    const auto& boxes = patch.GetVolume().Boxes;
    v.Dyadic = v.Dyadic &&
      vtkLRSplineElementLocator::ComputeDyadicLevels(boxes.data(),
        static_cast<vtkIdType>(boxes.size() / 6), patch.GetLocator().GetDomain(), levels);
    const auto& c = patch.GetVolume().Coefficients;
    const int nc = v.Components;
    for (std::size_t i = 0; i + nc <= c.size(); i += nc)
    {
      double m = 0.0;
      for (int k = 0; k < nc; ++k)
      {
        m += c[i + k] * c[i + k];
      }
      magnitudes.push_back(std::sqrt(m));
    }
  }
  // The transfer functions span [0, the largest magnitude of a Bernstein
  // coefficient] (the coefficients bound the spline).
  const double largestMagnitude =
    magnitudes.empty() ? 0.0 : *std::max_element(magnitudes.begin(), magnitudes.end());
  v.Range[0] = 0.0;
  v.Range[1] = largestMagnitude > 0 ? largestMagnitude : 1.0;
  if (v.DataRange[1] > v.DataRange[0])
  {
    // A fitted scan: the voxels' range (least squares overshoots it a little
    // at edges; the transfer functions clamp there).
    v.Range[0] = v.DataRange[0];
    v.Range[1] = v.DataRange[1];
  }
  double largest = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    largest = std::max(largest, v.Bounds[2 * k + 1] - v.Bounds[2 * k]);
  }
  v.Unit = (v.Foci.empty() ? 0.1 : 0.01) * largest;
  char text[400];
  std::snprintf(text, sizeof(text),
    "%lld elements in %d patch(es), degree %d, %d component(s)%s, %s knots, element sides "
    "%.3g ... %.3g (ratio %.0f, %.1f levels), transfer functions over [0, %.3g]",
    static_cast<long long>(v.Elements), v.Field->GetNumberOfPatches(), v.Degree, v.Components,
    v.Components > 1 ? " (rendered: the magnitude)" : "", v.Dyadic ? "dyadic" : "non-dyadic",
    v.MinSide, v.MaxSide, v.MaxSide / v.MinSide, std::log2(v.MaxSide / v.MinSide), v.Range[1]);
  v.Description = text;
  return true;
}

std::vector<lrbench::RefinedVolumeRecipe> Recipes()
{
  std::vector<lrbench::RefinedVolumeRecipe> r(3);
  r[0].Name = "refined-5k"; // Fuchs' fluidized bed: 5,311 elements, non-dyadic knots
  r[0].Dyadic = false;
  r[0].Levels = 6;
  r[0].NumberOfFoci = 2;
  r[1].Name = "refined-30k"; // Fuchs' wind case: 36,614 elements, 256x
  r[1].Dyadic = true;
  r[1].Levels = 8;
  r[1].NumberOfFoci = 10;
  r[2].Name = "refined-250k"; // Fuchs' MR brain: 255,909 elements, texture applies
  r[2].Dyadic = true;
  r[2].Levels = 5;
  r[2].NumberOfFoci = 190;
  return r;
}

vtkSmartPointer<vtkDataObject> Read(const std::string& path, double& seconds)
{
  vtkNew<vtkLRSplineReader> reader;
  reader->SetFileName(path.c_str());
  const double t0 = Now();
  reader->Update();
  seconds = Now() - t0;
  vtkMultiBlockDataSet* out = reader->GetOutput();
  if (!out || out->GetNumberOfBlocks() == 0)
  {
    return nullptr;
  }
  vtkSmartPointer<vtkDataObject> data = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  data->ShallowCopy(out);
  return data;
}

/// DIPY's real MR scan fitted here by vtkLRSplineImageFitter (quadratic,
/// least squares with local refinement until every voxel is within
/// `tolerance` of the data range), as the example lr_spline_fit_image.py
/// does; `seconds` is the fit's time (read and fit; excluded from the
/// rendering times like the reading of the files).
vtkSmartPointer<vtkDataObject> FitScan(
  const std::string& path, double tolerance, double& seconds, std::string& about, double range[2])
{
  if (!std::filesystem::exists(path))
  {
    about = "not found (python3-dipy not installed?)";
    return nullptr;
  }
  const double t0 = Now();
  vtkNew<vtkNIFTIImageReader> reader;
  reader->SetFileName(path.c_str());
  vtkNew<vtkLRSplineImageFitter> fitter;
  fitter->SetInputConnection(reader->GetOutputPort());
  fitter->SetDegree(2, 2, 2);
  fitter->SetToleranceModeToRelative();
  fitter->SetTolerance(tolerance);
  fitter->SetOutputFieldName("intensity");
  fitter->Update();
  seconds = Now() - t0;
  vtkMultiBlockDataSet* out = fitter->GetOutput();
  if (!out || out->GetNumberOfBlocks() == 0)
  {
    about = "the fit failed";
    return nullptr;
  }
  int dims[3];
  reader->GetOutput()->GetDimensions(dims);
  reader->GetOutput()->GetScalarRange(range);
  char text[300];
  std::snprintf(text, sizeof(text),
    "%s (%d x %d x %d voxels) fitted to %.3g of its range (max error %.4g, RMS %.4g, tolerance "
    "%s, %d refinement levels) in %.1f s",
    std::filesystem::path(path).filename().string().c_str(), dims[0], dims[1], dims[2], tolerance,
    fitter->GetMaximumError(), fitter->GetRMSError(), fitter->GetToleranceMet() ? "met" : "NOT met",
    fitter->GetNumberOfRefinementLevels(), seconds);
  about = text;
  vtkSmartPointer<vtkDataObject> data = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  data->ShallowCopy(out);
  return data;
}

//------------------------------------------------------------------------------
// Scene set-up shared by every method.
void ConfigureProperty(vtkVolumeProperty* property, const Volume& v, bool shade)
{
  const double a = v.Range[0], b = v.Range[1];
  if (v.DataRange[1] > v.DataRange[0])
  {
    // A scan: the background (below 8 % of the range) clear, tissue from
    // a haze to opaque.
    lrvolume::SetTransferFunctions(property, a, b, 0.25, 0.5,
      { { 0.0, 0.0 }, { 0.08, 0.0 }, { 0.25, 0.1 }, { 0.5, 0.6 }, { 1.0, 0.9 } });
  }
  else if (v.Foci.empty())
  {
    // The transfer functions of the volume tests (TestLRSplineVolumeReference).
    lrvolume::SetTransferFunctions(property, a, b);
  }
  else
  {
    // The generated volumes: the swirl (|v| < 0.4 of the largest value) a
    // faint haze, the cores at the foci (the detail the refinement is for)
    // opaque shells.
    lrvolume::SetTransferFunctions(
      property, a, b, 0.4, 0.55, { { 0.0, 0.0 }, { 0.4, 0.005 }, { 0.5, 0.5 }, { 1.0, 0.95 } });
  }
  property->SetScalarOpacityUnitDistance(v.Unit);
  property->SetInterpolationTypeToLinear();
  property->SetShade(shade ? 1 : 0);
  property->SetAmbient(0.25);
  property->SetDiffuse(0.7);
  property->SetSpecular(0.3);
  property->SetSpecularPower(20.0);
}

struct View
{
  std::string Name; // "overview" or "closeup"
  double Focus[3] = { 0, 0, 0 };
  double Zoom = 1.0;
  double Slab = 0.0; // > 0: only |(x - focus) . view direction| <= Slab is rendered
};

std::vector<View> Views(const Volume& v, const std::vector<std::string>& wanted)
{
  std::vector<View> views;
  for (const auto& name : wanted)
  {
    View view;
    view.Name = name;
    if (name == "closeup")
    {
      // The first focus, seen 40 finest elements wide (its core is 4 wide).
      if (!v.StronglyRefined || v.Foci.empty())
      {
        continue;
      }
      std::copy(v.Foci[0].begin(), v.Foci[0].end(), view.Focus);
      view.Zoom = 1.0 / (40.0 * v.MinSide);
      // A slab through the focus, as one looks at a detail (clipping planes
      // for every method): the rays cross the refined region, not the whole
      // volume (which also keeps the uniform-step reference affordable).
      view.Slab = 0.08;
    }
    views.push_back(view);
  }
  return views;
}

/// The camera of `view` (turned by `azimuth` degrees about its focal point).
void PlaceCamera(vtkRenderer* ren, const Volume& v, const View& view, double azimuth = 0.0)
{
  vtkCamera* cam = ren->GetActiveCamera();
  cam->SetFocalPoint(0, 0, 0);
  cam->SetPosition(0, 0, 1);
  cam->SetViewUp(0, 1, 0);
  cam->SetViewAngle(30.0);
  double bounds[6];
  std::copy(v.Bounds, v.Bounds + 6, bounds);
  ren->ResetCamera(bounds);
  cam->Azimuth(35.0);
  cam->Elevation(25.0);
  cam->OrthogonalizeViewUp();
  ren->ResetCamera(bounds);
  cam->Zoom(1.25);
  if (view.Name == "closeup")
  {
    double f[3], p[3];
    cam->GetFocalPoint(f);
    cam->GetPosition(p);
    for (int k = 0; k < 3; ++k)
    {
      p[k] += view.Focus[k] - f[k];
    }
    cam->SetFocalPoint(view.Focus);
    cam->SetPosition(p);
    cam->Zoom(view.Zoom / 1.25);
  }
  cam->Azimuth(azimuth);
  ren->ResetCameraClippingRange(bounds);
}

/// The close-up's slab as planes n . x + w >= 0 (data = world coordinates),
/// for the camera of `ren`.
std::vector<std::array<double, 4>> SlabPlanes(vtkRenderer* ren, const View& view)
{
  std::vector<std::array<double, 4>> planes;
  if (view.Slab <= 0.0)
  {
    return planes;
  }
  double d[3];
  ren->GetActiveCamera()->GetDirectionOfProjection(d);
  const double* f = view.Focus;
  const double fd = d[0] * f[0] + d[1] * f[1] + d[2] * f[2];
  planes.push_back({ d[0], d[1], d[2], -(fd - view.Slab) });
  planes.push_back({ -d[0], -d[1], -d[2], fd + view.Slab });
  return planes;
}

/// The same planes as a vtkPlaneCollection for a volume mapper (VTK's
/// convention: the side the normal points to is kept).
vtkSmartPointer<vtkPlaneCollection> PlaneCollection(
  const std::vector<std::array<double, 4>>& planes)
{
  auto collection = vtkSmartPointer<vtkPlaneCollection>::New();
  for (const auto& p : planes)
  {
    vtkNew<vtkPlane> plane;
    plane->SetNormal(p[0], p[1], p[2]);
    // origin: the point of the plane nearest to 0, -w n (n is a unit vector)
    plane->SetOrigin(-p[3] * p[0], -p[3] * p[1], -p[3] * p[2]);
    collection->AddItem(plane);
  }
  return collection;
}

/// An offscreen window without multisampling, its context made by an empty
/// frame (not part of any measurement).
/// With `floatColor`, the renderer draws into a 32-bit float color buffer
/// (vtkFramebufferPass), which is read for the image errors.
struct Window
{
  vtkNew<vtkRenderWindow> Win;
  vtkNew<vtkRenderer> Ren;
  vtkSmartPointer<vtkFramebufferPass> Float;
  Window(int width, int height, const double background[3] = Background, bool floatColor = false)
  {
    this->Win->SetOffScreenRendering(1);
    this->Win->SetMultiSamples(0);
    this->Win->SetSize(width, height);
    this->Ren->SetBackground(background[0], background[1], background[2]);
    this->Win->AddRenderer(this->Ren);
    if (floatColor)
    {
      vtkNew<vtkRenderStepsPass> steps;
      this->Float = vtkSmartPointer<vtkFramebufferPass>::New();
      this->Float->SetDelegatePass(steps);
      this->Float->SetColorFormat(vtkTextureObject::Float32);
      this->Float->SetDepthFormat(vtkTextureObject::Fixed32);
      this->Ren->SetPass(this->Float);
    }
    this->Win->Render();
    this->Win->WaitForCompletion();
  }
  Cost Frame()
  {
    const Stopwatch watch;
    this->Win->Render();
    this->Win->WaitForCompletion();
    return watch.Elapsed();
  }
  /// A volume of `mapper` with the benchmark's transfer functions for `v`
  /// (shaded or not) in the renderer; its property (held by the volume).
  vtkVolumeProperty* Show(const Volume& v, vtkAbstractVolumeMapper* mapper, bool shade)
  {
    vtkNew<vtkVolumeProperty> property;
    ConfigureProperty(property, v, shade);
    vtkNew<vtkVolume> volume;
    volume->SetMapper(mapper);
    volume->SetProperty(property);
    this->Ren->AddVolume(volume);
    return property;
  }
  /// The first frame of the overview (what it costs from the data in memory).
  Cost FirstFrame(const Volume& v)
  {
    PlaceCamera(this->Ren, v, View());
    return this->Frame();
  }
};

/// Median frame time (wall and CPU, each its median) over a camera orbit of
/// `frames` frames (at least 2 when `seconds` runs out); the camera is put
/// back afterwards.
Cost OrbitFrames(
  Window& w, const Volume& v, const View& view, int frames, double seconds, int* measured = nullptr)
{
  std::vector<double> wall, cpu;
  const double start = Now();
  for (int i = 1; i <= frames; ++i)
  {
    PlaceCamera(w.Ren, v, view, 360.0 * i / (frames + 1));
    const Cost c = w.Frame();
    wall.push_back(c.Wall);
    cpu.push_back(c.CPU);
    if (Now() - start > seconds && wall.size() >= 2)
    {
      break;
    }
  }
  PlaceCamera(w.Ren, v, view);
  if (measured)
  {
    *measured = static_cast<int>(wall.size());
  }
  return { Median(wall), Median(cpu) };
}

//------------------------------------------------------------------------------
// Our mapper.
struct OurConfig
{
  std::string Label;
  int Locator = vtkLRSplineVolumeMapper::KD_FOREST;
  int Resolution = 0; // forest trees per direction, 0: the mapper's automatic choice
  bool Adaptive = true;
  double StepScale = 1.0;
  double SampleDistance = 0.0; // world units, uniform steps
  int Supersampling = 4;       // the mapper's default
  bool Magnitude = true;       // else component 0
  /// Profiling only: text replaced in the fragment shader (see
  /// ProfiledVolumeMapper).
  std::vector<std::pair<std::string, std::string>> Replacements;
};

/// For profiling only: the mapper with parts of its fragment shader
/// replaced by text (the picture is wrong; the time says what that part
/// costs).
class ProfiledVolumeMapper : public vtkLRSplineVolumeMapper
{
public:
  static ProfiledVolumeMapper* New();
  vtkTypeMacro(ProfiledVolumeMapper, vtkLRSplineVolumeMapper);
  std::vector<std::pair<std::string, std::string>> Replacements;
  std::string Missing;

protected:
  std::string GetFragmentShaderSource() override
  {
    std::string fs = this->vtkLRSplineVolumeMapper::GetFragmentShaderSource();
    for (const auto& r : this->Replacements)
    {
      const std::size_t at = fs.find(r.first);
      if (at == std::string::npos)
      {
        this->Missing = r.first;
        continue;
      }
      fs.replace(at, r.first.size(), r.second);
    }
    return fs;
  }
};
vtkStandardNewMacro(ProfiledVolumeMapper);

vtkSmartPointer<vtkLRSplineVolumeMapper> MakeMapper(const Volume& v, const OurConfig& c)
{
  vtkSmartPointer<vtkLRSplineVolumeMapper> mapper;
  if (c.Replacements.empty())
  {
    mapper = vtkSmartPointer<vtkLRSplineVolumeMapper>::New();
  }
  else
  {
    auto profiled = vtkSmartPointer<ProfiledVolumeMapper>::New();
    profiled->Replacements = c.Replacements;
    mapper = profiled;
  }
  mapper->SetInputDataObject(v.Data);
  mapper->SetElementLocator(c.Locator);
  mapper->SetForestResolution(c.Resolution);
  mapper->SetAdaptiveSteps(c.Adaptive);
  mapper->SetStepScale(c.StepScale);
  mapper->SetSampleDistance(c.SampleDistance);
  mapper->SetSupersampling(c.Supersampling);
  mapper->SetVectorMode(
    c.Magnitude ? vtkLRSplineVolumeMapper::MAGNITUDE : vtkLRSplineVolumeMapper::COMPONENT);
  // MaximumNumberOfSteps 0: automatic, no ray is cut short.
  return mapper;
}

struct Timing
{
  bool Ok = false;
  std::string Error;
  Cost FirstFrame, Frame, FrameShaded;
  double GPUBytes = 0.0;
  int Frames = 0;
};

/// Time to first frame (the data in memory: GPU data built and uploaded,
/// shaders, the frame), then frames over an orbit, unshaded and shaded.
Timing TimeOurs(const Volume& v, const OurConfig& c, int width, int height, int frames,
  double seconds, bool shaded)
{
  Timing t;
  Window w(width, height);
  vtkSmartPointer<vtkLRSplineVolumeMapper> mapper = MakeMapper(v, c);
  vtkVolumeProperty* property = w.Show(v, mapper, false);
  const View overview;
  t.FirstFrame = w.FirstFrame(v);
  t.Error = mapper->GetLastErrorMessage();
  if (!t.Error.empty())
  {
    return t;
  }
  t.GPUBytes = static_cast<double>(mapper->GetGPUMemorySize());
  t.Frame = OrbitFrames(w, v, overview, frames, seconds, &t.Frames);
  if (shaded)
  {
    property->SetShade(1);
    w.Frame(); // the shaded program
    t.FrameShaded = OrbitFrames(w, v, overview, frames, seconds);
  }
  t.Ok = true;
  return t;
}

/// Where our frame goes: the default frame against frames with one part of
/// the work changed (profiling hints; the pictures of the changed shaders are
/// wrong).
void ProfileOurs(const Volume& v, int width, int height, int frames, double seconds)
{
  struct Variant
  {
    std::string Label;
    OurConfig Config;
  };
  std::vector<Variant> variants(6);
  variants[0].Label = "as measured (defaults)";
  variants[1].Label = "transfer function once per step (Supersampling 1, not 4)";
  variants[1].Config.Supersampling = 1;
  variants[2].Label = "one component instead of the magnitude of 3";
  variants[2].Config.Magnitude = false;
  variants[3].Label = "no coefficient fetches (constants instead)";
  variants[3].Config.Replacements = { { "return texelFetch(lrCoefficients, i).x;",
    "return 0.5 + 0.01 * float(i & 7);" } };
  variants[4].Label = "element search at every sample (no reuse)";
  variants[4].Config.Replacements = {
    { "if (p != lrCurrentPatch || any(lessThan(u, lrCurrentLo)) || "
      "any(greaterThan(u, lrCurrentHi)))",
      "if (true)" }
  };
  variants[5].Label = "no samples (the ray set-up only)";
  variants[5].Config.Replacements = { { "for (int step = 0; step < lrMaxSteps; ++step)",
    "for (int step = 0; step < 0; ++step)" } };
  if (v.Components == 1)
  {
    variants.erase(variants.begin() + 2);
  }
  std::printf("   where the frame goes, %dx%d, k-d forest default, unshaded:\n", width, height);
  Cost base;
  for (const Variant& variant : variants)
  {
    Window w(width, height);
    vtkSmartPointer<vtkLRSplineVolumeMapper> mapper = MakeMapper(v, variant.Config);
    auto* profiled = ProfiledVolumeMapper::SafeDownCast(mapper);
    w.Show(v, mapper, false);
    const View overview;
    w.FirstFrame(v);
    if (profiled && !profiled->Missing.empty())
    {
      std::printf("   %-58s the shader has changed: \"%.40s...\" not found\n",
        variant.Label.c_str(), profiled->Missing.c_str());
      continue;
    }
    const Cost t = OrbitFrames(w, v, overview, frames, seconds);
    if (base.Wall == 0.0)
    {
      base = t;
    }
    std::printf("   %-58s %8.0f ms (CPU %6.0f ms) %6.2f (CPU %4.2f)\n", variant.Label.c_str(),
      1000.0 * t.Wall, 1000.0 * t.CPU, t.Wall / base.Wall, t.CPU / base.CPU);
    std::fflush(stdout);
  }
}

/// An image in 8-bit units: as the window shows it (rounded), and, when
/// the window renders in float, not rounded.
struct Picture
{
  std::vector<double> Bits8, Float;
};

/// The picture of `mapper` in window `w` from `view` (with its slab).
Picture Snapshot(Window& w, const Volume& v, const View& view, vtkAbstractMapper* mapper)
{
  PlaceCamera(w.Ren, v, view);
  mapper->RemoveAllClippingPlanes();
  if (view.Slab > 0.0)
  {
    mapper->SetClippingPlanes(PlaneCollection(SlabPlanes(w.Ren, view)));
  }
  w.Win->Render();
  w.Win->WaitForCompletion();
  Picture p;
  p.Bits8 = lrvolume::ReadRGB(w.Win);
  if (w.Float)
  {
    p.Float = lrvolume::ReadRGBFloat(w.Float->GetColorTexture());
  }
  return p;
}

struct Samples
{
  double PerRay = 0.0; // mean over the pixels with a ray
  double Total = 0.0;
  double Most = 0.0; // the longest ray's
};

Samples CountSamples(const Volume& v, const OurConfig& c, const View& view, int width, int height)
{
  const double black[3] = { 0, 0, 0 };
  Window w(width, height, black);
  vtkSmartPointer<vtkLRSplineVolumeMapper> mapper = MakeMapper(v, c);
  mapper->SetCountSamples(true);
  w.Show(v, mapper, false);
  const std::vector<double> rgb = Snapshot(w, v, view, mapper).Bits8;
  Samples s;
  long long rays = 0;
  for (std::size_t p = 0; p + 2 < rgb.size(); p += 3)
  {
    const double n = rgb[p] + 256.0 * rgb[p + 1] + 65536.0 * rgb[p + 2];
    if (n > 0)
    {
      ++rays;
      s.Total += n;
      s.Most = std::max(s.Most, n);
    }
  }
  s.PerRay = rays > 0 ? s.Total / rays : 0.0;
  return s;
}

Picture OurImage(
  const Volume& v, const OurConfig& c, const View& view, int width, int height, bool shade)
{
  Window w(width, height, Background, true);
  vtkSmartPointer<vtkLRSplineVolumeMapper> mapper = MakeMapper(v, c);
  w.Show(v, mapper, shade);
  return Snapshot(w, v, view, mapper);
}

//------------------------------------------------------------------------------
// VTK's way.
struct Resampled
{
  int N = 0;
  bool Ok = false;
  std::string Why;
  Cost Seconds;
  vtkSmartPointer<vtkImageData> Image;
  double GPUBytes = 0.0;
};

/// Bytes VTK's way holds in main memory at N^3 (the resampled doubles and
/// mask, the smart mapper's magnitude image, the float copy it uploads and
/// llvmpipe's texture).
double VTKWayMemory(int n, int components)
{
  const double voxels = std::pow(static_cast<double>(n), 3);
  return voxels * (8.0 * components + 1.0 + (components > 1 ? 8.0 : 0.0) + 4.0 + 4.0);
}

Resampled Resample(const Volume& v, int n)
{
  Resampled r;
  r.N = n;
  const double need = VTKWayMemory(n, v.Components);
  const double available = AvailableMemory();
  if (available > 0 && need > 0.6 * available)
  {
    char why[200];
    std::snprintf(why, sizeof(why),
      "refused: needs about %.1f GB of memory, %.1f GB available (limit 60 %%)", need / 1e9,
      available / 1e9);
    r.Why = why;
    return r;
  }
  vtkNew<vtkLRSplineResampleToImage> resample;
  resample->SetInputDataObject(v.Data);
  resample->SetSamplingDimensions(n, n, n);
  const Stopwatch watch;
  resample->Update();
  r.Seconds = watch.Elapsed();
  r.Image = resample->GetOutput();
  if (!r.Image || r.Image->GetNumberOfPoints() != static_cast<vtkIdType>(n) * n * n)
  {
    r.Why = "resampling failed";
    return r;
  }
  // vtkVolumeTexture uploads doubles as one 32-bit float per voxel (R32F).
  r.GPUBytes = 4.0 * std::pow(static_cast<double>(n), 3);
  r.Ok = true;
  return r;
}

vtkSmartPointer<vtkSmartVolumeMapper> MakeVTKMapper(const Volume& v, vtkImageData* image)
{
  auto mapper = vtkSmartPointer<vtkSmartVolumeMapper>::New();
  mapper->SetInputData(image);
  mapper->SetRequestedRenderModeToGPU();
  // Deterministic quality: no sample-distance changes by frame rate; VTK's
  // own step (half the mean voxel spacing, SampleDistance -1).
  mapper->SetInteractiveAdjustSampleDistances(0);
  mapper->SetAutoAdjustSampleDistances(0);
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectScalarArray(v.Field->GetArrayName().c_str());
  if (v.Components > 1)
  {
    mapper->SetVectorMode(vtkSmartVolumeMapper::MAGNITUDE);
  }
  return mapper;
}

struct VTKTiming
{
  Cost FirstRender; // after the resampling
  Cost Frame;
  bool GPU = false;
};

VTKTiming TimeVTK(
  const Volume& v, vtkImageData* image, int width, int height, int frames, double seconds)
{
  VTKTiming t;
  Window w(width, height);
  vtkSmartPointer<vtkSmartVolumeMapper> mapper = MakeVTKMapper(v, image);
  w.Show(v, mapper, false);
  const View overview;
  t.FirstRender = w.FirstFrame(v);
  t.GPU = mapper->GetLastUsedRenderMode() == vtkSmartVolumeMapper::GPURenderMode;
  t.Frame = OrbitFrames(w, v, overview, frames, seconds);
  return t;
}

Picture VTKImage(const Volume& v, vtkImageData* image, const View& view, int width, int height)
{
  Window w(width, height, Background, true);
  vtkSmartPointer<vtkSmartVolumeMapper> mapper = MakeVTKMapper(v, image);
  w.Show(v, mapper, false);
  return Snapshot(w, v, view, mapper);
}

//------------------------------------------------------------------------------
// The CPU reference.
// Its images are in 8-bit units, not rounded.
struct Reference
{
  std::vector<double> RGB, RGBShaded;
  double Step = 0.0;
  double SelfError = 0.0; // RMS against the same rendering at twice the step
  double Seconds = 0.0;
};

/// Image errors (RMS per channel, 8-bit units) against a reference image:
/// of the float rendering, and of the 8-bit window against the rounded
/// reference (dominated by rounding when the difference is a small fraction
/// of a level).
struct Errors
{
  double Float = -1.0, Bits8 = -1.0;
};

Errors Compare(const Picture& picture, const std::vector<double>& reference)
{
  Errors e;
  std::vector<double> rounded(reference);
  for (double& x : rounded)
  {
    x = std::round(x);
  }
  e.Bits8 = lrvolume::RMS(picture.Bits8, rounded);
  if (!picture.Float.empty())
  {
    e.Float = lrvolume::RMS(picture.Float, reference);
  }
  return e;
}

Reference RenderReference(const Volume& v, const View& view, int width, int height, bool shaded)
{
  Reference ref;
  Window w(width, height);
  vtkNew<vtkVolumeProperty> property;
  ConfigureProperty(property, v, false);
  vtkNew<vtkVolume> volume; // only its property and (identity) matrix are used
  volume->SetProperty(property);
  PlaceCamera(w.Ren, v, view);
  lrvolume::View lv;
  lv.Set(w.Ren, volume);
  lrvolume::Settings settings;
  settings.Component = -1;
  settings.ClipPlanes = SlabPlanes(w.Ren, view);
  // Half the finest adaptive step, and at most a 2000th of the diagonal
  // (volumes of large elements, where the finest step is coarse).
  double diagonal = 0.0;
  for (int d = 0; d < 3; ++d)
  {
    diagonal += std::pow(v.Bounds[2 * d + 1] - v.Bounds[2 * d], 2.0);
  }
  ref.Step = std::min(v.FinestStep() / 2.0, std::sqrt(diagonal) / 2000.0);
  const double t0 = Now();
  settings.Step = ref.Step;
  ref.RGB =
    lrvolume::OverBackground(lrvolume::Render(*v.Field, volume, lv, settings), Background, false);
  settings.Step = 2.0 * ref.Step;
  ref.SelfError = lrvolume::RMS(ref.RGB,
    lrvolume::OverBackground(lrvolume::Render(*v.Field, volume, lv, settings), Background, false));
  if (shaded)
  {
    property->SetShade(1);
    settings.Shade = true;
    settings.Step = ref.Step;
    ref.RGBShaded =
      lrvolume::OverBackground(lrvolume::Render(*v.Field, volume, lv, settings), Background, false);
  }
  ref.Seconds = Now() - t0;
  return ref;
}

//------------------------------------------------------------------------------
// Curves of error against cost.
struct Point
{
  double Cost, Error;
};

/// The cost at which the curve (sorted by cost, error falling) reaches
/// `error`: log-log interpolation between the bracketing points. `status`:
/// 0 interpolated, +1 not reached (the largest cost returned), -1 already
/// reached by the cheapest point (its cost returned).
double CostAtError(std::vector<Point> curve, double error, int& status)
{
  std::sort(
    curve.begin(), curve.end(), [](const Point& a, const Point& b) { return a.Cost < b.Cost; });
  status = 1;
  if (curve.empty())
  {
    return 0.0;
  }
  if (curve.front().Error <= error)
  {
    status = -1;
    return curve.front().Cost;
  }
  for (std::size_t i = 1; i < curve.size(); ++i)
  {
    if (curve[i].Error <= error)
    {
      const Point& a = curve[i - 1];
      const Point& b = curve[i];
      status = 0;
      const double la = std::log(std::max(a.Error, 1e-12)), lb = std::log(std::max(b.Error, 1e-12));
      const double f = la > lb ? (la - std::log(std::max(error, 1e-12))) / (la - lb) : 1.0;
      return std::exp(std::log(a.Cost) + f * (std::log(b.Cost) - std::log(a.Cost)));
    }
  }
  return curve.back().Cost;
}

//------------------------------------------------------------------------------
struct Options
{
  std::vector<std::string> Volumes = { "external", "dipy-scan", "refined-5k", "refined-30k",
    "refined-250k" };
  std::string Scan = "/usr/lib/python3/dist-packages/dipy/data/files/aniso_vox.nii.gz";
  double FitTolerance = 0.05;
  std::vector<std::string> Files;
  std::vector<std::string> Sizes = { "640x360", "1280x720" };
  std::string ErrorSize = "128x72";
  std::vector<std::string> Locators = { "texture", "octree", "kdtree", "forest8", "forest64",
    "forest512", "default" };
  std::vector<std::string> Views = { "overview", "closeup" };
  std::vector<int> Resolutions = { 128, 256, 512 };
  int Frames = 3;
  double Seconds = 5.0;
  bool Shaded = true;
  bool Steps = true;
  bool Profile = false;
  bool AllStructuresEverySize = false;
  bool LargeResamplingEverywhere = false;
  std::string Cache;
  std::string Images; // where to write the error renderings as PNG ("": nowhere)
};

struct LocatorChoice
{
  const char* Name;
  const char* Label;
  int Type;
  int Resolution;
};

const LocatorChoice LocatorChoices[] = {
  { "texture", "look-up texture", vtkLRSplineElementLocator::TEXTURE, 0 },
  { "octree", "octree", vtkLRSplineElementLocator::OCTREE, 0 },
  { "kdtree", "k-d tree (forest 1^3)", vtkLRSplineElementLocator::KD_TREE, 0 },
  { "forest8", "k-d forest 8^3", vtkLRSplineElementLocator::KD_FOREST, 8 },
  { "forest64", "k-d forest 64^3", vtkLRSplineElementLocator::KD_FOREST, 64 },
  { "forest512", "k-d forest 512^3", vtkLRSplineElementLocator::KD_FOREST, 512 },
  { "default", "k-d forest, default", vtkLRSplineElementLocator::KD_FOREST, 0 },
};

/// What a volume's runs found, for the summary.
struct Findings
{
  std::string Volume;
  bool StronglyRefined = false;
  std::map<std::string, Cost> OurFirst, VTK256First; // per window size
  double OurBytes = 0.0;
  std::map<std::string, double> OurError;                // per view
  std::map<std::string, std::map<int, double>> VTKError; // per view, per resolution
  std::map<int, Cost> VTKFirst;                          // at the first window size
  std::map<int, Cost> VTKResample;
  std::map<int, double> VTKBytes;
  std::map<std::string, double> AdaptiveSamples, UniformSamples, EqualError;
  std::map<std::string, int> UniformStatus;
};

std::string Seconds(const Cost& c)
{
  char text[64];
  std::snprintf(text, sizeof(text), "%.2f s (CPU %.2f s)", c.Wall, c.CPU);
  return text;
}

std::string Milliseconds(const Cost& c)
{
  char text[64];
  std::snprintf(text, sizeof(text), "%6.0f (%6.0f)", 1000.0 * c.Wall, 1000.0 * c.CPU);
  return text;
}

/// Write an error rendering (8-bit units) for inspection, when asked to.
void WriteImage(
  const Options& o, const std::vector<double>& rgb, int width, int height, const std::string& name)
{
  if (o.Images.empty() || rgb.empty())
  {
    return;
  }
  std::error_code ec;
  std::filesystem::create_directories(o.Images, ec);
  lrvolume::WritePNG(
    rgb, width, height, (std::filesystem::path(o.Images) / (name + ".png")).string());
}

void RunVolume(Volume& v, const Options& o, bool profile, Findings& found)
{
  std::printf("\n== %s: %s\n", v.Name.c_str(), v.Description.c_str());
  if (!v.Source.empty())
  {
    std::printf("   %s\n", v.Source.c_str());
  }
  std::printf("   read%s in %.2f s (excluded from every time below); load average %.1f\n",
    v.Source.empty() ? "" : " and fitted", v.ReadSeconds, LoadAverage());
  std::fflush(stdout);
  found.Volume = v.Name;
  found.StronglyRefined = v.StronglyRefined;
  int ew = 160, eh = 90;
  splineviz_benchmark::ParseSize(o.ErrorSize, ew, eh);

  // Warm shader caches (Mesa keeps compiled shaders on disk; every rerun
  // starts warm), so that first frames compare the same way.
  {
    OurConfig c;
    OurImage(v, c, View(), 32, 18, false);
    OurImage(v, c, View(), 32, 18, true);
    Resampled tiny = Resample(v, 16);
    if (tiny.Ok)
    {
      VTKImage(v, tiny.Image, View(), 32, 18);
    }
  }

  // --- The CPU reference per view.
  const std::vector<View> views = Views(v, o.Views);
  std::map<std::string, Reference> refs;
  for (const View& view : views)
  {
    refs[view.Name] = RenderReference(v, view, ew, eh, o.Shaded);
    const Reference& r = refs[view.Name];
    WriteImage(o, r.RGB, ew, eh, v.Name + "-" + view.Name + "-reference");
    WriteImage(o, r.RGBShaded, ew, eh, v.Name + "-" + view.Name + "-reference-shaded");
    std::printf("   CPU reference, %s%s, %dx%d: step %.3g (%.2g of the finest adaptive step), "
                "%.1f s; its own error (against twice the step) %.4f / 255\n",
      view.Name.c_str(), view.Slab > 0 ? " (a slab through the first focus)" : "", ew, eh, r.Step,
      r.Step / v.FinestStep(), r.Seconds, r.SelfError);
    std::fflush(stdout);
  }

  // --- Element search structures (Fuchs' tables).
  std::printf("\n-- %s: element search structures\n", v.Name.c_str());
  struct Row
  {
    std::string Label;
    bool Ok = false;
    std::string Why;
    double Build = 0.0;
    vtkLRSplineElementLocator::Statistics Stats;
    int Blocks = 0;
    std::map<std::string, Timing> Times;
  };
  std::vector<Row> rows;
  for (const LocatorChoice& choice : LocatorChoices)
  {
    if (std::find(o.Locators.begin(), o.Locators.end(), choice.Name) == o.Locators.end())
    {
      continue;
    }
    Row row;
    row.Label = choice.Label;
    {
      vtkLRSplineField field;
      std::string error;
      const int blocks[3] = { choice.Resolution, choice.Resolution, choice.Resolution };
      const double t0 = Now();
      row.Ok = field.Build(
        v.Data, nullptr, choice.Type, choice.Resolution > 0 ? blocks : nullptr, false, &error);
      row.Build = Now() - t0;
      if (!row.Ok)
      {
        row.Why = error;
        rows.push_back(row);
        continue;
      }
      std::vector<vtkLRSplineElementLocator::Statistics> stats;
      for (int p = 0; p < field.GetNumberOfPatches(); ++p)
      {
        stats.push_back(field.GetPatch(p).GetLocator().GetStatistics());
      }
      row.Stats = lrbench::CombineStatistics(stats);
      row.Blocks = field.GetPatch(0).GetLocator().GetNumberOfBlocks()[0];
      if (std::string(choice.Name) == "default")
      {
        row.Label = "k-d forest " + std::to_string(row.Blocks) + "^3 (default)";
      }
    }
    OurConfig c;
    c.Locator = choice.Type;
    c.Resolution = choice.Resolution;
    for (const auto& size : o.Sizes)
    {
      if (size != o.Sizes.front() && !o.AllStructuresEverySize &&
        std::string(choice.Name) != "default")
      {
        continue; // the other structures at the first size only (time)
      }
      int w = 0, h = 0;
      splineviz_benchmark::ParseSize(size, w, h);
      Timing t = TimeOurs(v, c, w, h, o.Frames, o.Seconds, o.Shaded);
      if (!t.Ok)
      {
        row.Ok = false;
        row.Why = t.Error;
        break;
      }
      if (std::string(choice.Name) == "default")
      {
        found.OurFirst[size] = t.FirstFrame;
        found.OurBytes = t.GPUBytes;
      }
      row.Times[size] = t;
      std::printf("   %-28s %-9s first frame %s, frame %.0f ms\n", row.Label.c_str(), size.c_str(),
        Seconds(t.FirstFrame).c_str(), 1000.0 * t.Frame.Wall);
      std::fflush(stdout);
    }
    rows.push_back(row);
  }
  std::printf("\n   %-28s %7s %s %9s\n", "structure", "build s",
    lrbench::StatisticsHeader().c_str(), "GPU MB");
  for (const Row& r : rows)
  {
    if (!r.Ok)
    {
      std::printf("   %-28s not applicable: %.100s\n", r.Label.c_str(), r.Why.c_str());
      continue;
    }
    std::printf("   %-28s %7.2f %s %9.1f\n", r.Label.c_str(), r.Build,
      lrbench::StatisticsRow(r.Stats).c_str(), MB(r.Times.begin()->second.GPUBytes));
  }
  for (const auto& size : o.Sizes)
  {
    std::printf("\n   %-9s %-28s %21s %17s %17s %8s\n", size.c_str(), "structure",
      "first frame s (CPU)", "frame ms (CPU)", "shaded ms (CPU)", "shading");
    for (const Row& r : rows)
    {
      if (!r.Ok || !r.Times.count(size))
      {
        continue;
      }
      const Timing& t = r.Times.at(size);
      std::printf("   %-9s %-28s %9.2f (%8.2f)  %s  %s %7.2fx\n", size.c_str(), r.Label.c_str(),
        t.FirstFrame.Wall, t.FirstFrame.CPU, Milliseconds(t.Frame).c_str(),
        o.Shaded ? Milliseconds(t.FrameShaded).c_str() : "      -         ",
        t.Frame.CPU > 0 && o.Shaded ? t.FrameShaded.CPU / t.Frame.CPU : 0.0);
    }
  }
  std::fflush(stdout);

  if (profile)
  {
    int w = 0, h = 0;
    splineviz_benchmark::ParseSize(o.Sizes.front(), w, h);
    std::printf("\n");
    ProfileOurs(v, w, h, o.Frames, o.Seconds);
  }

  // --- Our image error, and adaptive against uniform steps.
  OurConfig defaults;
  for (const View& view : views)
  {
    const Reference& ref = refs[view.Name];
    const Picture picture = OurImage(v, defaults, view, ew, eh, false);
    WriteImage(o, picture.Bits8, ew, eh, v.Name + "-" + view.Name + "-ours");
    const Errors ours = Compare(picture, ref.RGB);
    found.OurError[view.Name] = ours.Float;
    std::printf("\n-- %s, %s: our image error (default settings) %.3f / 255 (8-bit window: "
                "%.3f)",
      v.Name.c_str(), view.Name.c_str(), ours.Float, ours.Bits8);
    if (o.Shaded)
    {
      const Errors shaded = Compare(OurImage(v, defaults, view, ew, eh, true), ref.RGBShaded);
      std::printf(", shaded %.3f (8-bit %.3f)", shaded.Float, shaded.Bits8);
    }
    std::printf("\n");
    const Samples asIs = CountSamples(v, defaults, view, ew, eh);
    std::printf("   samples per ray %.1f, longest ray %.0f\n", asIs.PerRay, asIs.Most);
    if (!o.Steps)
    {
      continue;
    }
    std::printf("   steps (%dx%d)                   samples/ray   longest   total samples   "
                "image error / 255\n",
      ew, eh);
    std::vector<Point> uniform, adaptive;
    double defaultError = 0.0;
    for (double scale : { 4.0, 2.0, 1.0, 0.5 })
    {
      OurConfig c = defaults;
      c.StepScale = scale;
      const Samples n = CountSamples(v, c, view, ew, eh);
      const Picture steps = OurImage(v, c, view, ew, eh, false);
      WriteImage(o, steps.Bits8, ew, eh,
        v.Name + "-" + view.Name + "-adaptive-" + std::to_string(scale).substr(0, 3));
      const double e = Compare(steps, ref.RGB).Float;
      std::printf("   adaptive, StepScale %-4g %19.1f %9.0f %15.3e %12.3f\n", scale, n.PerRay,
        n.Most, n.Total, e);
      std::fflush(stdout);
      adaptive.push_back({ n.Total, e });
      if (scale == 1.0)
      {
        defaultError = e;
      }
    }
    double previousMost = 0.0;
    for (double k : { 32.0, 16.0, 8.0, 4.0, 2.0, 1.0 })
    {
      OurConfig c = defaults;
      c.Adaptive = false;
      c.SampleDistance = k * v.FinestStep(); // the volume's matrix is the identity
      const Samples n = CountSamples(v, c, view, ew, eh);
      const Picture steps = OurImage(v, c, view, ew, eh, false);
      WriteImage(o, steps.Bits8, ew, eh,
        v.Name + "-" + view.Name + "-uniform-" + std::to_string(static_cast<int>(k)));
      const double e = Compare(steps, ref.RGB).Float;
      // Halving the step doubles the longest ray unless a limit cuts it
      // (llvmpipe ends a fragment's loops after 65,535 iterations in all:
      // measured, uniform rays stop near 4,090 samples).
      const bool cut = previousMost > 100.0 && n.Most < 1.5 * previousMost;
      previousMost = n.Most;
      std::printf("   uniform, %2g x finest step %16.1f %9.0f %15.3e %12.3f%s\n", k, n.PerRay,
        n.Most, n.Total, e, cut ? "   (rays cut by the loop limit: not used)" : "");
      std::fflush(stdout);
      if (!cut)
      {
        uniform.push_back({ n.Total, e });
      }
    }
    // Equal error: the adaptive default's error, or the smallest error any
    // uniform step reaches when that is larger (in single precision the
    // error of very small steps grows again: thousands of tiny opacities
    // composited); each method's samples at that error, interpolated on
    // its curve down to its smallest error.
    if (uniform.empty())
    {
      continue;
    }
    auto descending = [](std::vector<Point> curve)
    {
      std::sort(
        curve.begin(), curve.end(), [](const Point& a, const Point& b) { return a.Cost < b.Cost; });
      std::size_t best = 0;
      for (std::size_t i = 0; i < curve.size(); ++i)
      {
        best = curve[i].Error < curve[best].Error ? i : best;
      }
      curve.resize(best + 1);
      return curve;
    };
    const std::vector<Point> u = descending(uniform), a = descending(adaptive);
    const double target = std::max(defaultError, u.back().Error);
    int su = 0, sa = 0;
    const double needU = CostAtError(u, target, su);
    const double needA = CostAtError(a, target, sa);
    found.EqualError[view.Name] = target;
    found.AdaptiveSamples[view.Name] = needA;
    found.UniformSamples[view.Name] = needU;
    found.UniformStatus[view.Name] = su < 0 ? -1 : (sa < 0 ? 1 : 0);
    std::printf("   at equal error %.3f (%s): uniform steps %.3e samples, adaptive steps %.3e: "
                "%s%.2fx fewer\n",
      target, target > defaultError ? "the smallest uniform error" : "the adaptive default's",
      needU, needA, su < 0 ? "at most " : (sa < 0 ? "at least " : ""), needU / needA);
  }
  std::fflush(stdout);

  // --- VTK's way.
  std::printf("\n-- %s: VTK's way, vtkLRSplineResampleToImage + vtkSmartVolumeMapper "
              "(GPU ray casting, magnitude by its vector mode, linear interpolation, its step)\n",
    v.Name.c_str());
  for (int n : o.Resolutions)
  {
    if (n > 256 && !v.StronglyRefined && !o.LargeResamplingEverywhere)
    {
      std::printf("   %d^3: skipped (time: only on the strongly refined volume, where the "
                  "targets are measured; --large-resampling-everywhere)\n",
        n);
      continue;
    }
    Resampled r = Resample(v, n);
    if (!r.Ok)
    {
      std::printf("   %d^3: %s\n", n, r.Why.c_str());
      continue;
    }
    found.VTKBytes[n] = r.GPUBytes;
    found.VTKResample[n] = r.Seconds;
    std::printf("   %d^3: resampled in %s; GPU texture %.1f MB\n", n, Seconds(r.Seconds).c_str(),
      MB(r.GPUBytes));
    for (const auto& size : o.Sizes)
    {
      int w = 0, h = 0;
      splineviz_benchmark::ParseSize(size, w, h);
      const VTKTiming t = TimeVTK(v, r.Image, w, h, o.Frames, o.Seconds);
      const Cost first = r.Seconds + t.FirstRender;
      if (size == o.Sizes.front())
      {
        found.VTKFirst[n] = first;
      }
      if (n == 256)
      {
        found.VTK256First[size] = first;
      }
      std::printf("   %d^3, %-9s first frame %s (render %.2f s), frame %s ms%s\n", n, size.c_str(),
        Seconds(first).c_str(), t.FirstRender.Wall, Milliseconds(t.Frame).c_str(),
        t.GPU ? "" : " (NOT the GPU mapper)");
      std::fflush(stdout);
    }
    for (const View& view : views)
    {
      const Picture picture = VTKImage(v, r.Image, view, ew, eh);
      WriteImage(o, picture.Bits8, ew, eh, v.Name + "-" + view.Name + "-vtk" + std::to_string(n));
      const Errors e = Compare(picture, refs[view.Name].RGB);
      found.VTKError[view.Name][n] = e.Float;
      std::printf("   %d^3, %-9s image error %.3f / 255 (8-bit window: %.3f)\n", n,
        view.Name.c_str(), e.Float, e.Bits8);
    }
    std::fflush(stdout);
  }

  // --- The curve.
  for (const View& view : views)
  {
    std::printf("\n-- %s, %s: image error against cost (first frame and GPU memory at %s)\n",
      v.Name.c_str(), view.Name.c_str(), o.Sizes.front().c_str());
    std::printf("   %-26s %12s %26s %10s\n", "method", "error / 255", "first frame", "GPU MB");
    for (const auto& e : found.VTKError[view.Name])
    {
      std::printf("   %-26s %12.3f %26s %10.1f\n",
        ("resampled to " + std::to_string(e.first) + "^3").c_str(), e.second,
        Seconds(found.VTKFirst[e.first]).c_str(), MB(found.VTKBytes[e.first]));
    }
    std::printf("   %-26s %12.3f %26s %10.1f\n", "vtkLRSplineVolumeMapper",
      found.OurError[view.Name], Seconds(found.OurFirst[o.Sizes.front()]).c_str(),
      MB(found.OurBytes));
  }
  std::fflush(stdout);
}

void PrintTargets(const std::vector<Findings>& all, const Options& o)
{
  std::printf(
    "\n== Targets; times at %s, wall clock (CPU time in brackets)\n", o.Sizes.front().c_str());
  // 1. The strongly refined volume at equal image error.
  for (const Findings& f : all)
  {
    if (!f.StronglyRefined || !f.OurFirst.count(o.Sizes.front()))
    {
      continue;
    }
    const Cost ours = f.OurFirst.at(o.Sizes.front());
    for (const auto& view : f.OurError)
    {
      const double error = view.second;
      const std::map<int, double>& curve = f.VTKError.at(view.first);
      if (curve.empty())
      {
        std::printf("1. %s, %s: no resampling measured\n", f.Volume.c_str(), view.first.c_str());
        continue;
      }
      int reached = 0;
      for (const auto& e : curve)
      {
        if (e.second <= error)
        {
          reached = e.first;
          break;
        }
      }
      const int n = reached ? reached : curve.rbegin()->first;
      const Cost vtk = f.VTKFirst.at(n);
      const double wall = vtk.Wall / ours.Wall, cpu = vtk.CPU / ours.CPU;
      const double bytes = f.OurBytes / f.VTKBytes.at(n);
      const bool met = wall >= 5.0 && cpu >= 5.0 && bytes <= 0.1;
      std::printf("1. %s, %s: our error %.3f / 255; ", f.Volume.c_str(), view.first.c_str(), error);
      if (reached)
      {
        std::printf("%d^3 is the first resampling to reach it (%.3f)", n, curve.at(n));
      }
      else
      {
        std::printf("no resampling up to %d^3 reaches it (%d^3: %.3f, %.1fx ours)", n, n,
          curve.at(n), curve.at(n) / error);
      }
      std::printf(": against %d^3, first frame %.1fx (CPU %.1fx) shorter (target 5x), GPU memory "
                  "%.3fx (target <= 0.1): %s\n",
        n, wall, cpu, bytes,
        met
          ? (reached ? "MET" : "MET (a resampling that reaches our error is larger and costs more)")
          : "NOT MET");
      if (!reached && curve.size() >= 2)
      {
        // Extrapolated: error ~ N^slope through the two finest resolutions.
        auto last = curve.rbegin();
        auto before = std::next(last);
        const double slope = std::log(last->second / before->second) /
          std::log(static_cast<double>(last->first) / before->first);
        if (slope > -0.5)
        {
          std::printf("   (the error falls as N^%.2f between the two largest resamplings: too "
                      "slowly to extrapolate)\n",
            slope);
        }
        else
        {
          const double needed = last->first * std::pow(error / last->second, 1.0 / slope);
          const double scale = std::pow(needed / last->first, 3.0);
          std::printf("   extrapolated (error ~ N^%.2f): about %.0f^3 would reach it: %.0f GB of "
                      "texture (%.0fx ours), resampling alone about %.0f s (%.0fx our first "
                      "frame)\n",
            slope, needed, 4.0 * std::pow(needed, 3.0) / 1e9,
            4.0 * std::pow(needed, 3.0) / f.OurBytes, f.VTKResample.at(last->first).Wall * scale,
            f.VTKResample.at(last->first).Wall * scale / ours.Wall);
        }
      }
    }
  }
  // 2. Never slower to the first frame than resampling to 256^3.
  for (const Findings& f : all)
  {
    for (const auto& size : o.Sizes)
    {
      if (!f.OurFirst.count(size) || !f.VTK256First.count(size))
      {
        continue;
      }
      const Cost ours = f.OurFirst.at(size), vtk = f.VTK256First.at(size);
      std::printf("2. %s, %s: our first frame %s, resampling to 256^3 + first frame %s: %.2fx "
                  "(CPU %.2fx): %s\n",
        f.Volume.c_str(), size.c_str(), Seconds(ours).c_str(), Seconds(vtk).c_str(),
        vtk.Wall / ours.Wall, vtk.CPU / ours.CPU,
        ours.Wall <= vtk.Wall && ours.CPU <= vtk.CPU
          ? "MET"
          : (ours.Wall <= vtk.Wall || ours.CPU <= vtk.CPU ? "MET in one clock only" : "NOT MET"));
    }
  }
  // 3. Adaptive steps: at least 2x fewer samples than uniform steps at equal error.
  for (const Findings& f : all)
  {
    for (const auto& view : f.AdaptiveSamples)
    {
      const double ratio = f.UniformSamples.at(view.first) / view.second;
      const int status = f.UniformStatus.at(view.first);
      std::printf("3. %s, %s: at equal error %.3f uniform steps need %s%.2fx the samples of "
                  "adaptive steps: %s\n",
        f.Volume.c_str(), view.first.c_str(), f.EqualError.at(view.first),
        status < 0 ? "at most " : (status > 0 ? "at least " : ""), ratio,
        ratio >= 2.0
          ? (status < 0 ? "undecided (the coarsest uniform step already reaches it)" : "MET")
          : (status > 0 ? "undecided" : "NOT MET"));
    }
  }
}
}

const char* const Usage =
  "Usage: BenchmarkLRSplineVolume [options]\n"
  "Direct volume rendering of LR-spline volumes (vtkLRSplineVolumeMapper) against\n"
  "vtkLRSplineResampleToImage + vtkSmartVolumeMapper, side by side, with image errors\n"
  "against the CPU reference renderer.\n"
  "  --quick                 external, dipy-scan and refined-30k, 640x360, fewer structures\n"
  "                          and frames, 128^3 and 256^3 (roughly a third of the full run)\n"
  "  --volumes a,b,...       external, dipy-scan, refined-5k, refined-30k, refined-250k\n"
  "                          (default: all)\n"
  "  --scan FILE.nii.gz      the real scan fitted for dipy-scan (default: DIPY's aniso_vox)\n"
  "  --fit-tolerance T       its fit's tolerance, a fraction of the range (default 0.05)\n"
  "  --volume FILE.lr        also render this .lr file\n"
  "  --sizes WxH,...         window sizes (default 640x360,1280x720)\n"
  "  --error-size WxH        size of the image-error renderings (default 128x72)\n"
  "  --locators a,b,...      texture, octree, kdtree, forest8, forest64, forest512, default\n"
  "  --views a,b             overview, closeup (the close-up: strongly refined volume only)\n"
  "  --resample N,...        VTK's resampling resolutions (default 128,256,512)\n"
  "  --frames N              frames after the first (default 3)\n"
  "  --seconds S             stop an orbit after S seconds (at least 2 frames; default 5)\n"
  "  --no-shading            skip the shaded frames and errors\n"
  "  --no-steps              skip adaptive against uniform steps\n"
  "  --profile               profile our frame (shader parts replaced) on the strongly\n"
  "                          refined volume\n"
  "  --all-structures-every-size  every element search structure at every window size\n"
  "                          (default: all at the first size, the default at the others)\n"
  "  --large-resampling-everywhere  resample above 256^3 on every volume (default: on the\n"
  "                          strongly refined one only)\n"
  "  --cache DIR             where generated volumes are kept (default: <temp>/splineviz-\n"
  "                          benchmark-cache)\n"
  "  --images DIR            write the error renderings (reference, ours, VTK's) as PNG\n";

int main(int argc, char* argv[])
{
  if (splineviz_benchmark::HelpRequested(argc, argv, Usage))
  {
    return 0;
  }
  vtkSMPTools::SetBackend("STDThread");
  Options o;
  {
    std::error_code ec;
    std::filesystem::path tmp = std::filesystem::temp_directory_path(ec);
    o.Cache = ((ec ? std::filesystem::path(".") : tmp) / "splineviz-benchmark-cache").string();
  }
  for (int i = 1; i < argc; ++i)
  {
    const std::string key = argv[i];
    auto value = [&]() -> std::string
    {
      if (i + 1 >= argc)
      {
        std::fprintf(stderr, "option %s needs a value\n%s", key.c_str(), Usage);
        std::exit(2);
      }
      return argv[++i];
    };
    if (key == "--quick")
    {
      o.Volumes = { "external", "dipy-scan", "refined-30k" };
      o.Sizes = { "640x360" };
      o.ErrorSize = "128x72";
      o.Locators = { "octree", "kdtree", "default" };
      o.Resolutions = { 128, 256 };
      o.Frames = 3;
      o.Seconds = 6.0;
    }
    else if (key == "--volumes")
      o.Volumes = Split(value());
    else if (key == "--volume")
      o.Files.push_back(value());
    else if (key == "--scan")
      o.Scan = value();
    else if (key == "--fit-tolerance")
      o.FitTolerance = std::atof(value().c_str());
    else if (key == "--sizes")
      o.Sizes = Split(value());
    else if (key == "--error-size")
      o.ErrorSize = value();
    else if (key == "--locators")
      o.Locators = Split(value());
    else if (key == "--views")
      o.Views = Split(value());
    else if (key == "--resample")
    {
      o.Resolutions.clear();
      for (const auto& s : Split(value()))
      {
        o.Resolutions.push_back(std::atoi(s.c_str()));
      }
    }
    else if (key == "--frames")
      o.Frames = std::atoi(value().c_str());
    else if (key == "--seconds")
      o.Seconds = std::atof(value().c_str());
    else if (key == "--no-shading")
      o.Shaded = false;
    else if (key == "--no-steps")
      o.Steps = false;
    else if (key == "--profile")
      o.Profile = true;
    else if (key == "--all-structures-every-size")
      o.AllStructuresEverySize = true;
    else if (key == "--large-resampling-everywhere")
      o.LargeResamplingEverywhere = true;
    else if (key == "--cache")
      o.Cache = value();
    else if (key == "--images")
      o.Images = value();
    else
    {
      std::fprintf(stderr, "unknown option %s\n%s", key.c_str(), Usage);
      return 2;
    }
  }
  std::vector<std::string> knownLocators;
  for (const auto& c : LocatorChoices)
  {
    knownLocators.push_back(c.Name);
  }
  if (!splineviz_benchmark::AllKnown(o.Volumes,
        { "external", "dipy-scan", "refined-5k", "refined-30k", "refined-250k" }, "volume") ||
    !splineviz_benchmark::AllKnown(o.Locators, knownLocators, "element search structure") ||
    !splineviz_benchmark::AllKnown(o.Views, { "overview", "closeup" }, "view") ||
    !splineviz_benchmark::ValidSizes(o.Sizes, Usage) ||
    !splineviz_benchmark::ValidSizes({ o.ErrorSize }, Usage) || o.Frames < 1 || o.Sizes.empty())
  {
    return 2;
  }
  for (int n : o.Resolutions)
  {
    if (n < 2 || n > 2048)
    {
      std::fprintf(stderr, "resampling resolution %d out of range (2 ... 2048)\n", n);
      return 2;
    }
  }
  const double start = Now();
  std::printf("LR-spline volume rendering benchmark; vtkSMPTools %s, %d threads; cache %s; "
              "load average %.1f\n",
    vtkSMPTools::GetBackend(), vtkSMPTools::GetEstimatedNumberOfThreads(), o.Cache.c_str(),
    LoadAverage());
  {
    Window w(16, 16);
    const std::string caps = w.Win->ReportCapabilities();
    const std::size_t at = caps.find("OpenGL renderer string:");
    if (at != std::string::npos)
    {
      std::printf("%s\n", caps.substr(at, caps.find('\n', at) - at).c_str());
    }
  }

  // The volumes: the external file, DIPY's scan fitted here, the generated
  // ones (cached), any --volume files.
  std::vector<Volume> volumes;
  for (const auto& name : o.Volumes)
  {
    Volume v;
    v.Name = name;
    std::string path;
    if (name == "external")
    {
      path = SPLINEVIZ_EXTERNAL_DATA_DIR "/cube-3patch-refined.lr";
    }
    else if (name == "dipy-scan")
    {
      std::string about;
      v.Data = FitScan(o.Scan, o.FitTolerance, v.ReadSeconds, about, v.DataRange);
      if (!v.Data)
      {
        std::printf("dipy-scan: %s: %s: skipped\n", o.Scan.c_str(), about.c_str());
        continue;
      }
      v.Source = about;
    }
    else
    {
      for (auto& recipe : Recipes())
      {
        if (recipe.Name != name)
        {
          continue;
        }
        bool generated = false;
        const double t0 = Now();
        path = lrbench::CachedRefinedVolume(recipe, o.Cache, &generated);
        std::printf("%s: %s %s (%.1f s)\n", name.c_str(), generated ? "generated" : "cached",
          path.c_str(), Now() - t0);
        v.Foci = recipe.FociCache;
        v.StronglyRefined = recipe.Levels >= 8;
      }
    }
    if (!v.Data)
    {
      v.Data = path.empty() ? nullptr : Read(path, v.ReadSeconds);
    }
    if (!v.Data || !Describe(v))
    {
      std::fprintf(stderr, "ERROR: cannot load volume %s\n", name.c_str());
      return 1;
    }
    volumes.push_back(std::move(v));
  }
  for (const auto& file : o.Files)
  {
    Volume v;
    v.Name = std::filesystem::path(file).filename().string();
    v.Data = Read(file, v.ReadSeconds);
    if (!v.Data || !Describe(v))
    {
      std::fprintf(stderr, "ERROR: cannot load volume %s\n", file.c_str());
      return 1;
    }
    volumes.push_back(std::move(v));
  }

  // The profile of our frame runs on the strongly refined volume (else the first).
  std::size_t profiled = 0;
  for (std::size_t i = 0; i < volumes.size(); ++i)
  {
    if (volumes[i].StronglyRefined)
    {
      profiled = i;
      break;
    }
  }
  std::vector<Findings> all;
  for (std::size_t i = 0; i < volumes.size(); ++i)
  {
    Findings f;
    RunVolume(volumes[i], o, o.Profile && i == profiled, f);
    all.push_back(f);
  }
  PrintTargets(all, o);
  std::printf(
    "\nwhole run: %.1f min; load average at the end %.1f\n", (Now() - start) / 60.0, LoadAverage());
  return 0;
}
