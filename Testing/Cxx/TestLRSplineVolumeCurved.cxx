// SPDX-License-Identifier: BSD-3-Clause
// vtkLRSplineVolumeMapper on curved (non-affine) multi-patch geometry: the
// two patches of cube-2patch.lr with every coefficient bent by a smooth map
// and a scalar field (a quasi-interpolant of sin(pi x) sin(pi y) sin(pi z))
// on the same basis, read in geometry mode. The GPU's rays march in
// physical space and invert the geometry map per sample; the reference is
// the CPU ray caster of LRSplineVolumeTestUtilities.h (double precision,
// uniform steps a quarter of the finest) over lrtest::PhysicalField, an
// evaluation written independently of SplineViz from the LRSplines texts
// (Cox-de Boor, Newton on the patch parameter). That evaluation is first
// checked against vtkLRSplineField at random points (1e-9; a rational field
// must differ from the polynomial one). RMS at most 3/255. Negative control:
// the same data with the geometry ignored (LRMode 0: the field over the
// parameter box) must fail the comparison. The fixed steps also in passes
// of 64 samples (the multi-pass continuation on curved geometry), and a
// rational variant (random positive weights on geometry and field, the
// homogeneous coefficients (w x, w) and (w f, w)); a shader that leaves the
// weight out of the field must fail. Isosurfaces (f = +-0.3, shaded) against
// the reference's bisection; the geometry ignored must fail there too.
// IFEM-Poisson's result on the bent patches: the analytic solution
// u = sin(pi x) sin(pi y) sin(pi z) of cube-2patch.xinp projected onto the
// basis by least squares (8 points per element, the basis by Cox-de Boor,
// as Testing/Python/ifem_poisson.py does), rendered at a fixed step against
// the CPU ray marcher at the same step over the ANALYTIC u at the physical
// points, masked by the reference's inversion (inside the patches); the
// analytic field with a wrong phase (cos(pi z)) or shifted by 0.1 must fail.
#include "LRSplinePhysicalReference.h"
#include "LRSplineVolumeTestUtilities.h"

#include "vtkLRSplineArrayNames.h"
#include "vtkLRSplineReader.h"
#include "vtkLRSplineVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIntArray.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <chrono>
#include <random>
#include <fstream>
#include <iostream>
#include <sstream>

namespace
{
const double Pi = 3.14159265358979323846;

// The LRSplines text with bent coefficients (field false) or with the
// scalar coefficients f (field true): sin(pi x) sin(pi y) sin(pi z) at the
// unbent coefficient, or `values` (one per basis function, in the text's
// order). Rational: homogeneous coefficients (w c, w) with random weights,
// the same sequence for the geometry and the field.
std::string BentOrField(
  const std::string& text, bool field, bool rational, const std::vector<double>* values = nullptr)
{
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> weight(0.5, 2.0);
  std::size_t next = 0;
  auto coefficient = [&](const double x[3], double* v)
  {
    if (!field)
    {
      lrvolume::Bend(x, v);
      return;
    }
    v[0] = values && next < values->size()
      ? (*values)[next++]
      : std::sin(Pi * x[0]) * std::sin(Pi * x[1]) * std::sin(Pi * x[2]);
  };
  return lrvolume::RewriteCoefficients(text, field ? 1 : 3, coefficient,
    rational ? std::function<double()>([&]() { return weight(rng); }) : nullptr);
}

// The bent patches with the scalar "f" (the fourth component) as active
// scalars; `ignoreGeometry`: marked as field mode (LRMode 0).
vtkSmartPointer<vtkMultiBlockDataSet> CurvedData(const std::string& text, bool ignoreGeometry,
  bool rational = false, const std::vector<double>* values = nullptr)
{
  // Both read element by element (no merged points): the same points in
  // the same order, so the field's coefficients attach to the geometry's.
  vtkNew<vtkLRSplineReader> reader;
  reader->ReadFromInputStringOn();
  reader->SetInputString(BentOrField(text, false, rational));
  reader->GeometryModeOn();
  reader->SetRationalMode(rational ? 2 : 1);
  reader->MergePointsOff();
  reader->Update();
  vtkNew<vtkLRSplineReader> fieldReader;
  fieldReader->ReadFromInputStringOn();
  fieldReader->SetInputString(BentOrField(text, true, rational, values));
  fieldReader->SetRationalModeToPolynomial(); // (w f, w): divided below
  fieldReader->MergePointsOff();
  fieldReader->Update();
  auto out = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  out->DeepCopy(reader->GetOutputDataObject(0));
  auto* fields = vtkMultiBlockDataSet::SafeDownCast(fieldReader->GetOutputDataObject(0));
  for (unsigned b = 0; b < out->GetNumberOfBlocks(); ++b)
  {
    auto* g = vtkUnstructuredGrid::SafeDownCast(out->GetBlock(b));
    auto* fg = fields ? vtkUnstructuredGrid::SafeDownCast(fields->GetBlock(b)) : nullptr;
    vtkDataArray* all = fg ? fg->GetPointData()->GetArray("Field") : nullptr;
    if (!g || !all || all->GetNumberOfComponents() != (rational ? 2 : 1) ||
      all->GetNumberOfTuples() != g->GetNumberOfPoints())
    {
      return nullptr;
    }
    vtkNew<vtkDoubleArray> f;
    f->SetName("f");
    f->SetNumberOfTuples(all->GetNumberOfTuples());
    for (vtkIdType i = 0; i < all->GetNumberOfTuples(); ++i)
    {
      // The field's Bezier coefficient (rational: over its Bezier weight).
      f->SetValue(i, all->GetComponent(i, 0) / (rational ? all->GetComponent(i, 1) : 1.0));
    }
    g->GetPointData()->RemoveArray("Field");
    g->GetPointData()->SetScalars(f);
    if (ignoreGeometry)
    {
      vtkNew<vtkIntArray> mode;
      mode->SetName(vtkLRSplineArrayNames::Mode);
      mode->InsertNextValue(0);
      g->GetFieldData()->AddArray(mode);
    }
  }
  return out;
}

// A mapper whose shader forgets to divide a rational field by the weight.
class NoWeightMapper : public vtkLRSplineVolumeMapper
{
public:
  static NoWeightMapper* New();
  vtkTypeMacro(NoWeightMapper, vtkLRSplineVolumeMapper);

protected:
  std::string GetFragmentShaderSource() override
  {
    std::string fs = this->vtkLRSplineVolumeMapper::GetFragmentShaderSource();
    const std::string from = "lrValue(lrCurrentOffset, lrCurrentS, gs) / lrCurrentW;";
    const std::size_t at = fs.find(from);
    if (at == std::string::npos)
    {
      std::cerr << "ERROR: the mutation target is not in the shader" << std::endl;
      return fs;
    }
    return fs.replace(at, from.size(), "lrValue(lrCurrentOffset, lrCurrentS, gs);");
  }
};
vtkStandardNewMacro(NoWeightMapper);

struct Result
{
  double RMS = -1;
  double Seconds = 0;
  int Passes = 0;
};

// The GPU's picture of `data` against the CPU reference ray marcher over the
// independent evaluation `reference` (computed once into `cpu`, written as
// TestLRSplineVolumeCurved-<cpuTag>.png); `sameStep`: the reference at the
// mapper's fixed step.
template <class Reference>
Result Compare(vtkMultiBlockDataSet* data, const Reference& reference, const std::string& cpuTag,
  const std::string& tag, std::vector<double>& cpu, double sampleDistance, int stepsPerPass = 0,
  bool noWeight = false, bool iso = false, bool sameStep = false, int width = 120, int height = 90)
{
  const double background[3] = { 0.1, 0.1, 0.12 };
  vtkSmartPointer<vtkLRSplineVolumeMapper> mapper = noWeight
    ? vtkSmartPointer<vtkLRSplineVolumeMapper>(vtkSmartPointer<NoWeightMapper>::New())
    : vtkSmartPointer<vtkLRSplineVolumeMapper>::New();
  mapper->SetInputDataObject(data);
  mapper->SetFieldArray("f");
  mapper->SetMaximumStepsPerPass(stepsPerPass);
  if (sampleDistance > 0)
  {
    mapper->AdaptiveStepsOff();
    mapper->SetSampleDistance(sampleDistance);
  }
  vtkNew<vtkColorTransferFunction> ctf;
  ctf->AddRGBPoint(-1.0, 0.05, 0.15, 0.9);
  ctf->AddRGBPoint(-0.3, 0.1, 0.8, 0.9);
  ctf->AddRGBPoint(0.3, 0.95, 0.9, 0.2);
  ctf->AddRGBPoint(1.0, 0.9, 0.1, 0.05);
  vtkNew<vtkPiecewiseFunction> otf;
  otf->AddPoint(-1.0, 0.8);
  otf->AddPoint(-0.2, 0.05);
  otf->AddPoint(0.2, 0.05);
  otf->AddPoint(1.0, 0.8);
  vtkNew<vtkVolumeProperty> property;
  property->SetColor(ctf);
  property->SetScalarOpacity(otf);
  property->SetScalarOpacityUnitDistance(0.1);
  // Isosurfaces: f = -0.3 and 0.3 (one in each patch), shaded.
  const std::vector<double> isoValues = { -0.3, 0.3 };
  if (iso)
  {
    mapper->SetBlendModeToIsoSurface();
    property->ShadeOn();
    for (std::size_t i = 0; i < isoValues.size(); ++i)
    {
      property->GetIsoSurfaceValues()->SetValue(static_cast<int>(i), isoValues[i]);
    }
  }
  lrvolume::Scene scene(mapper, property, width, height, background);
  // The same camera for every variant: the physical data's box.
  double bounds[6] = { -1.1, 1.2, -0.1, 1.2, -0.1, 1.2 };
  scene.SetCamera(bounds, 35, 25, 1.2);
  vtkVolume* volume = scene.Volume;
  vtkRenderer* ren = scene.Renderer;
  vtkRenderWindow* win = scene.Window;
  win->Render();
  Result result;
  if (!mapper->UpdateSpline() || std::string(mapper->GetLastErrorMessage()) != "")
  {
    std::cerr << "ERROR: " << tag << ": " << mapper->GetLastErrorMessage() << std::endl;
    return result;
  }
  const auto t0 = std::chrono::steady_clock::now();
  win->Render();
  result.Seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const std::vector<double> gpu = lrvolume::ReadRGB(win);
  const std::string out = std::string(SPLINEVIZ_TEST_OUTPUT_DIR) + "/TestLRSplineVolumeCurved-";
  lrvolume::WritePNG(gpu, width, height, out + tag + ".png");
  if (cpu.empty())
  {
    lrvolume::View view;
    view.Set(ren, volume);
    lrvolume::Settings settings;
    // A quarter of the mapper's finest adaptive step (side / 4): the
    // reference at a tenth differs from it by 0.2/255 RMS. With
    // `sameStep`, the mapper's fixed step.
    settings.Step = sameStep ? sampleDistance : reference.MinimumSide() / 4.0 / 4.0;
    if (iso)
    {
      settings.BlendMode = 5;
      settings.Shade = true;
      settings.IsoValues = isoValues;
    }
    const auto c0 = std::chrono::steady_clock::now();
    cpu = lrvolume::OverBackground(lrvolume::Render(reference, volume, view, settings), background);
    std::cout << cpuTag << ": "
              << std::chrono::duration<double>(std::chrono::steady_clock::now() - c0).count()
              << " s" << std::endl;
    lrvolume::WritePNG(cpu, width, height, out + cpuTag + ".png");
    const long long covered = lrvolume::CountNonBackground(cpu, background);
    if (covered < width * height / (iso ? 16 : 8))
    {
      std::cerr << "ERROR: the reference covers only " << covered << " pixels" << std::endl;
      return result;
    }
  }
  result.RMS = lrvolume::RMS(gpu, cpu);
  lrvolume::WritePNG(gpu, width, height, out + tag + "-diff.png", &cpu);
  result.Passes = mapper->GetNumberOfPasses();
  std::cout << tag << ": RMS " << result.RMS << " / 255, frame " << result.Seconds << " s, "
            << result.Passes << " passes" << std::endl;
  return result;
}
// The production CPU evaluation (vtkLRSplineField on the geometry-mode
// data) against the independent one at random points of the physical box:
// the same inside / outside and values within 1e-9. The largest difference,
// or -1 when inside / outside disagree at more than a handful of points
// (points within rounding of the boundary may go either way).
double CrossCheck(vtkMultiBlockDataSet* data, const lrtest::PhysicalField& reference)
{
  vtkLRSplineField field;
  std::string error;
  if (!field.Build(data, "f", vtkLRSplineElementLocator::KD_FOREST, nullptr, false, &error))
  {
    std::cerr << "ERROR: " << error << std::endl;
    return -1;
  }
  double bounds[6];
  reference.GetBounds(bounds);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double worst = 0.0;
  int disagree = 0, inside = 0;
  for (int i = 0; i < 2000; ++i)
  {
    double x[3];
    for (int k = 0; k < 3; ++k)
    {
      x[k] = bounds[2 * k] + unit(rng) * (bounds[2 * k + 1] - bounds[2 * k]);
    }
    double a = 0, b = 0, ga[3], gb[3];
    const bool inA = field.Evaluate(x, &a, ga) >= 0;
    const bool inB = reference.Evaluate(x, &b, gb) >= 0;
    if (inA != inB)
    {
      ++disagree;
      continue;
    }
    if (inA)
    {
      ++inside;
      worst = std::max(worst, std::abs(a - b));
    }
  }
  std::cout << "cross-check: " << inside << " of 2000 points inside, " << disagree
            << " disagree on inside, largest difference " << worst << std::endl;
  return disagree > 2 || inside < 1000 ? -1.0 : worst;
}

// IFEM-Poisson's analytic solution of cube-2patch.xinp (with `phase` added
// to pi z, plus `shift`) and its gradient at physical x.
double Poisson(const double x[3], double gradient[3], double phase = 0.0, double shift = 0.0)
{
  const double s[3] = { std::sin(Pi * x[0]), std::sin(Pi * x[1]), std::sin(Pi * x[2] + phase) };
  const double c[3] = { std::cos(Pi * x[0]), std::cos(Pi * x[1]), std::cos(Pi * x[2] + phase) };
  gradient[0] = Pi * c[0] * s[1] * s[2];
  gradient[1] = Pi * s[0] * c[1] * s[2];
  gradient[2] = Pi * s[0] * s[1] * c[2];
  return s[0] * s[1] * s[2] + shift;
}

// The least-squares projection of Poisson() onto each patch's basis of the
// (bent) geometry text: 2 x 2 x 2 points per element at the quarters of its
// parameter box, the basis functions gamma B_u B_v B_w by Cox-de Boor, the
// normal equations by Cholesky. The coefficients in the text's order, or
// empty when a system is singular.
std::vector<double> ProjectPoisson(const std::string& geometryText)
{
  std::vector<double> out;
  for (const lrtest::BrutePatch& P : lrtest::ParseLR(geometryText))
  {
    const std::size_t n = P.Gamma.size();
    std::vector<double> N(n * n, 0.0), r(n, 0.0), b(n);
    std::vector<std::size_t> active;
    for (const auto& box : P.Elements)
    {
      for (int q = 0; q < 8; ++q)
      {
        double u[3], x[3] = { 0, 0, 0 }, g[3];
        for (int d = 0; d < 3; ++d)
        {
          u[d] = box[d] + ((q >> d & 1) ? 0.75 : 0.25) * (box[d + 3] - box[d]);
        }
        active.clear();
        for (std::size_t i = 0; i < n; ++i)
        {
          b[i] = P.Gamma[i];
          for (int d = 0; d < 3 && b[i] != 0.0; ++d)
          {
            b[i] *= lrtest::TruncatedPowerBSpline(P.Knots[i][d], u[d], false);
          }
          if (b[i] != 0.0)
          {
            active.push_back(i);
            for (int k = 0; k < 3; ++k)
            {
              x[k] += b[i] * P.Coef[P.Dim * i + k];
            }
          }
        }
        const double f = Poisson(x, g);
        for (std::size_t i : active)
        {
          r[i] += b[i] * f;
          for (std::size_t j : active)
          {
            N[i * n + j] += b[i] * b[j];
          }
        }
      }
    }
    // Cholesky N = L L^T (L in the lower triangle), then two substitutions.
    for (std::size_t j = 0; j < n; ++j)
    {
      for (std::size_t k = 0; k < j; ++k)
      {
        N[j * n + j] -= N[j * n + k] * N[j * n + k];
      }
      if (!(N[j * n + j] > 1e-14))
      {
        return {};
      }
      N[j * n + j] = std::sqrt(N[j * n + j]);
      for (std::size_t i = j + 1; i < n; ++i)
      {
        for (std::size_t k = 0; k < j; ++k)
        {
          N[i * n + j] -= N[i * n + k] * N[j * n + k];
        }
        N[i * n + j] /= N[j * n + j];
      }
    }
    for (std::size_t i = 0; i < n; ++i)
    {
      for (std::size_t k = 0; k < i; ++k)
      {
        r[i] -= N[i * n + k] * r[k];
      }
      r[i] /= N[i * n + i];
    }
    for (std::size_t i = n; i-- > 0;)
    {
      for (std::size_t k = i + 1; k < n; ++k)
      {
        r[i] -= N[k * n + i] * r[k];
      }
      r[i] /= N[i * n + i];
    }
    out.insert(out.end(), r.begin(), r.end());
  }
  return out;
}

// The analytic Poisson solution where the independent reference finds the
// physical point inside the patches (its inversion), for the CPU ray
// marcher: the spline's own value is discarded, so only the field differs.
struct AnalyticPoissonField
{
  const lrtest::PhysicalField* Geometry = nullptr;
  double Phase = 0.0, Shift = 0.0;

  int GetNumberOfComponents() const { return 1; }
  void GetBounds(double bounds[6]) const { this->Geometry->GetBounds(bounds); }
  double MinimumSide() const { return this->Geometry->MinimumSide(); }
  template <class Index>
  int EvaluateWithHint(
    const double x[3], double* value, double* gradient, int& patch, Index& element) const
  {
    const int p = this->Geometry->EvaluateWithHint(x, value, gradient, patch, element);
    if (p >= 0)
    {
      value[0] = Poisson(x, gradient, this->Phase, this->Shift);
    }
    return p;
  }
};
}

int TestLRSplineVolumeCurved(int, char*[])
{
  std::ifstream file(std::string(SPLINEVIZ_EXTERNAL_DATA_DIR) + "/cube-2patch.lr");
  std::stringstream buffer;
  buffer << file.rdbuf();
  const std::string text = buffer.str();
  vtkSmartPointer<vtkMultiBlockDataSet> curved = CurvedData(text, false);
  vtkSmartPointer<vtkMultiBlockDataSet> ignored = CurvedData(text, true);
  vtkSmartPointer<vtkMultiBlockDataSet> rational = CurvedData(text, false, true);
  // The independent references from the same texts.
  lrtest::PhysicalField polynomialReference, rationalReference;
  std::string error;
  if (!curved || !ignored || !rational ||
    !polynomialReference.Build(
      BentOrField(text, false, false), BentOrField(text, true, false), false, &error) ||
    !rationalReference.Build(
      BentOrField(text, false, true), BentOrField(text, true, true), true, &error))
  {
    std::cerr << "ERROR: the bent patches were not read as expected " << error << std::endl;
    return EXIT_FAILURE;
  }
  int failures = 0;
  // The independent evaluation agrees with the production one (and tells
  // the rational field from the polynomial one: the negative control).
  const double polynomialCheck = CrossCheck(curved, polynomialReference);
  const double rationalCheck = CrossCheck(rational, rationalReference);
  const double mixedCheck = CrossCheck(curved, rationalReference);
  if (!(polynomialCheck >= 0 && polynomialCheck < 1e-9 && rationalCheck >= 0 &&
        rationalCheck < 1e-9))
  {
    std::cerr << "ERROR: the CPU evaluations differ: " << polynomialCheck << ", " << rationalCheck
              << std::endl;
    ++failures;
  }
  if (mixedCheck >= 0 && mixedCheck < 1e-3)
  {
    std::cerr << "ERROR: the cross-check cannot tell a rational field from a polynomial one"
              << std::endl;
    ++failures;
  }
  std::vector<double> cpu;
  const Result adaptive = Compare(curved, polynomialReference, "cpu", "adaptive", cpu, 0.0);
  if (!(adaptive.RMS >= 0 && adaptive.RMS <= 3.0))
  {
    std::cerr << "ERROR: curved geometry, adaptive steps: RMS " << adaptive.RMS << std::endl;
    ++failures;
  }
  const Result fixed = Compare(curved, polynomialReference, "cpu", "fixed", cpu, 0.01);
  if (!(fixed.RMS >= 0 && fixed.RMS <= 3.0))
  {
    std::cerr << "ERROR: curved geometry, fixed steps: RMS " << fixed.RMS << std::endl;
    ++failures;
  }
  // The same fixed steps continued over several passes (64 samples each).
  const Result passes = Compare(curved, polynomialReference, "cpu", "passes", cpu, 0.01, 64);
  if (!(passes.RMS >= 0 && passes.RMS <= 3.0) || passes.Passes < 3)
  {
    std::cerr << "ERROR: curved geometry in passes: RMS " << passes.RMS << ", " << passes.Passes
              << " passes" << std::endl;
    ++failures;
  }
  // Rational geometry (random weights) with a field on the rational basis.
  std::vector<double> cpuRational;
  const Result nurbs =
    Compare(rational, rationalReference, "cpu-rational", "rational", cpuRational, 0.0);
  if (!(nurbs.RMS >= 0 && nurbs.RMS <= 3.0))
  {
    std::cerr << "ERROR: rational curved geometry: RMS " << nurbs.RMS << std::endl;
    ++failures;
  }
  const Result noWeight = Compare(
    rational, rationalReference, "cpu-rational", "rational-no-weight", cpuRational, 0.0, 0, true);
  if (!(noWeight.RMS > 3.0))
  {
    std::cerr << "ERROR: the negative control (the weight left out) passed: RMS " << noWeight.RMS
              << std::endl;
    ++failures;
  }
  // Isosurfaces on the curved geometry (bisection on the mapped field).
  std::vector<double> cpuIso;
  const Result iso =
    Compare(curved, polynomialReference, "cpu-iso", "iso", cpuIso, 0.0, 0, false, true);
  if (!(iso.RMS >= 0 && iso.RMS <= 3.0))
  {
    std::cerr << "ERROR: isosurfaces on curved geometry: RMS " << iso.RMS << std::endl;
    ++failures;
  }
  const Result wrongIso = Compare(
    ignored, polynomialReference, "cpu-iso", "iso-geometry-ignored", cpuIso, 0.0, 0, false, true);
  if (!(wrongIso.RMS > 3.0))
  {
    std::cerr << "ERROR: the negative control (isosurfaces, geometry ignored) passed: RMS "
              << wrongIso.RMS << std::endl;
    ++failures;
  }
  const Result wrong = Compare(ignored, polynomialReference, "cpu", "geometry-ignored", cpu, 0.0);
  if (!(wrong.RMS > 3.0))
  {
    std::cerr << "ERROR: the negative control (geometry ignored) passed: RMS " << wrong.RMS
              << std::endl;
    ++failures;
  }
  // IFEM-Poisson's result (the analytic u projected onto the bent patches'
  // basis) against the analytic u itself, the same fixed step both sides.
  const auto p0 = std::chrono::steady_clock::now();
  const std::vector<double> poissonValues = ProjectPoisson(BentOrField(text, false, false));
  vtkSmartPointer<vtkMultiBlockDataSet> poisson =
    poissonValues.empty() ? nullptr : CurvedData(text, false, false, &poissonValues);
  lrtest::PhysicalField poissonReference;
  if (!poisson ||
    !poissonReference.Build(BentOrField(text, false, false),
      BentOrField(text, true, false, &poissonValues), false, &error))
  {
    std::cerr << "ERROR: the Poisson result was not built " << error << std::endl;
    return EXIT_FAILURE;
  }
  const double poissonCheck = CrossCheck(poisson, poissonReference);
  double projectionError = 0.0;
  {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    double bounds[6], f, g[3], a[3];
    poissonReference.GetBounds(bounds);
    for (int i = 0; i < 2000; ++i)
    {
      double x[3];
      for (int k = 0; k < 3; ++k)
      {
        x[k] = bounds[2 * k] + unit(rng) * (bounds[2 * k + 1] - bounds[2 * k]);
      }
      if (poissonReference.Evaluate(x, &f, g) >= 0)
      {
        projectionError = std::max(projectionError, std::abs(f - Poisson(x, a)));
      }
    }
  }
  std::cout << "Poisson: projection error " << projectionError << ", built and checked in "
            << std::chrono::duration<double>(std::chrono::steady_clock::now() - p0).count() << " s"
            << std::endl;
  if (!(poissonCheck >= 0 && poissonCheck < 1e-9 && projectionError < 2.5e-2))
  {
    std::cerr << "ERROR: the Poisson result: cross-check " << poissonCheck << ", projection error "
              << projectionError << std::endl;
    ++failures;
  }
  // A smaller picture and a coarser step (the same on both sides) than the
  // cases above keep the test fast.
  const double poissonStep = poissonReference.MinimumSide() / 8.0;
  AnalyticPoissonField analytic;
  analytic.Geometry = &poissonReference;
  std::vector<double> cpuAnalytic;
  const Result poissonResult = Compare(poisson, analytic, "cpu-analytic", "poisson", cpuAnalytic,
    poissonStep, 0, false, false, true, 96, 72);
  if (!(poissonResult.RMS >= 0 && poissonResult.RMS <= 3.0))
  {
    std::cerr << "ERROR: the Poisson result against the analytic field: RMS " << poissonResult.RMS
              << std::endl;
    ++failures;
  }
  // Negative controls: the analytic field with the wrong phase, or shifted.
  const double controls[2][2] = { { 0.5 * Pi, 0.0 }, { 0.0, 0.1 } };
  const char* controlTags[2] = { "cos", "shifted" };
  for (int c = 0; c < 2; ++c)
  {
    AnalyticPoissonField wrongField = analytic;
    wrongField.Phase = controls[c][0];
    wrongField.Shift = controls[c][1];
    std::vector<double> cpuWrong;
    const Result control = Compare(poisson, wrongField,
      std::string("cpu-analytic-") + controlTags[c], std::string("poisson-vs-") + controlTags[c],
      cpuWrong, poissonStep, 0, false, false, true, 96, 72);
    if (!(control.RMS > 3.0))
    {
      std::cerr << "ERROR: the negative control (analytic field, " << controlTags[c]
                << ") passed: RMS " << control.RMS << std::endl;
      ++failures;
    }
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
