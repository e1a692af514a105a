// vtkLRSplineVolumeMapper on curved (non-affine) multi-patch geometry: the
// two patches of cube-2patch.lr with every coefficient bent by a smooth map
// and a fourth coefficient component, a scalar quasi-interpolant of
// sin(pi x) sin(pi y) sin(pi z), read in geometry mode. The GPU's rays march
// in physical space and invert the geometry map per sample; the reference is
// the CPU ray caster of LRSplineVolumeTestUtilities.h (double precision,
// uniform steps a tenth of the finest, evaluation by vtkLRSplineField, i.e.
// the C++ inversion, not the shader's). RMS at most 3/255. Negative control:
// the same data with the geometry ignored (LRMode 0: the field over the
// parameter box) must fail the comparison. The fixed steps also in passes
// of 64 samples (the multi-pass continuation on curved geometry).
#include "LRSplineVolumeTestUtilities.h"

#include "vtkLRSplineReader.h"
#include "vtkLRSplineVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIntArray.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <chrono>
#include <fstream>
#include <iostream>
#include <sstream>

namespace
{
const double Pi = 3.14159265358979323846;

void Bend(const double x[3], double y[3])
{
  y[0] = x[0] + 0.12 * std::sin(Pi * x[1]) * std::sin(Pi * x[2]);
  y[1] = x[1] + 0.10 * std::sin(Pi * x[0]) + 0.05 * x[2] * x[2];
  y[2] = x[2] + 0.08 * std::sin(2 * Pi * x[0]) * x[1];
}

// The LRSplines text with bent coefficients (field false) or with the
// scalar coefficients f (field true).
std::string BentOrField(const std::string& text, bool field)
{
  std::istringstream in(text);
  std::ostringstream out;
  out.precision(17);
  std::string line;
  bool header = false;
  while (std::getline(in, line))
  {
    if (line.find("# LRSPLINE") == 0)
    {
      header = true;
      out << line << "\n";
      continue;
    }
    if (header && !line.empty() && line[0] != '#')
    {
      std::istringstream h(line);
      int v[8];
      for (int& x : v)
      {
        h >> x;
      }
      v[6] = field ? 1 : 3;
      for (int i = 0; i < 8; ++i)
      {
        out << v[i] << (i < 7 ? " " : "\n");
      }
      header = false;
      continue;
    }
    const auto close = line.rfind(']');
    const auto paren = line.rfind('(');
    if (line.find(": [") != std::string::npos && close != std::string::npos &&
      paren != std::string::npos && paren > close)
    {
      std::istringstream c(line.substr(close + 1, paren - close - 1));
      double x[3], y[3];
      c >> x[0] >> x[1] >> x[2];
      Bend(x, y);
      const double f = std::sin(Pi * x[0]) * std::sin(Pi * x[1]) * std::sin(Pi * x[2]);
      out << line.substr(0, close + 1) << " ";
      if (field)
      {
        out << f;
      }
      else
      {
        out << y[0] << " " << y[1] << " " << y[2];
      }
      out << " " << line.substr(paren) << "\n";
      continue;
    }
    out << line << "\n";
  }
  return out.str();
}

// The bent patches with the scalar "f" (the fourth component) as active
// scalars; `ignoreGeometry`: marked as field mode (LRMode 0).
vtkSmartPointer<vtkMultiBlockDataSet> CurvedData(const std::string& text, bool ignoreGeometry)
{
  // Both read element by element (no merged points): the same points in
  // the same order, so the field's coefficients attach to the geometry's.
  vtkNew<vtkLRSplineReader> reader;
  reader->ReadFromInputStringOn();
  reader->SetInputString(BentOrField(text, false));
  reader->GeometryModeOn();
  reader->MergePointsOff();
  reader->Update();
  vtkNew<vtkLRSplineReader> fieldReader;
  fieldReader->ReadFromInputStringOn();
  fieldReader->SetInputString(BentOrField(text, true));
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
    if (!g || !all || all->GetNumberOfComponents() != 1 ||
      all->GetNumberOfTuples() != g->GetNumberOfPoints())
    {
      return nullptr;
    }
    vtkNew<vtkDoubleArray> f;
    f->SetName("f");
    f->SetNumberOfTuples(all->GetNumberOfTuples());
    for (vtkIdType i = 0; i < all->GetNumberOfTuples(); ++i)
    {
      f->SetValue(i, all->GetComponent(i, 0));
    }
    g->GetPointData()->RemoveArray("Field");
    g->GetPointData()->SetScalars(f);
    if (ignoreGeometry)
    {
      vtkNew<vtkIntArray> mode;
      mode->SetName("LRMode");
      mode->InsertNextValue(0);
      g->GetFieldData()->AddArray(mode);
    }
  }
  return out;
}

struct Result
{
  double RMS = -1;
  double Seconds = 0;
  int Passes = 0;
};

Result Compare(vtkMultiBlockDataSet* data, vtkMultiBlockDataSet* physical, const std::string& tag,
  std::vector<double>& cpu, double sampleDistance, int stepsPerPass = 0)
{
  const int width = 120, height = 90;
  const double background[3] = { 0.1, 0.1, 0.12 };
  vtkNew<vtkLRSplineVolumeMapper> mapper;
  mapper->SetInputDataObject(data);
  mapper->SetFieldArrayName("f");
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
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  vtkNew<vtkRenderer> ren;
  ren->SetBackground(background[0], background[1], background[2]);
  ren->AddVolume(volume);
  vtkNew<vtkRenderWindow> win;
  win->SetMultiSamples(0);
  win->SetSize(width, height);
  win->AddRenderer(ren);
  // The same camera for every variant: the physical data's box.
  double bounds[6] = { -1.1, 1.2, -0.1, 1.2, -0.1, 1.2 };
  ren->ResetCamera(bounds);
  ren->GetActiveCamera()->Azimuth(35);
  ren->GetActiveCamera()->Elevation(25);
  ren->ResetCamera(bounds);
  ren->GetActiveCamera()->Zoom(1.2);
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
    vtkLRSplineField field;
    std::string error;
    if (!field.Build(physical, "f", vtkLRSplineElementLocator::KD_FOREST, nullptr, false, &error))
    {
      std::cerr << "ERROR: " << error << std::endl;
      return result;
    }
    lrvolume::View view;
    view.Set(ren, volume);
    lrvolume::Settings settings;
    settings.Step = lrvolume::MinimumElementSide(field) / 4.0 / 10.0;
    cpu = lrvolume::OverBackground(lrvolume::Render(field, volume, view, settings), background);
    lrvolume::WritePNG(cpu, width, height, out + "cpu.png");
    const long long covered = lrvolume::CountNonBackground(cpu, background);
    if (covered < width * height / 8)
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
}

int TestLRSplineVolumeCurved(int, char*[])
{
  std::ifstream file(std::string(SPLINEVIZ_EXTERNAL_DATA_DIR) + "/cube-2patch.lr");
  std::stringstream buffer;
  buffer << file.rdbuf();
  vtkSmartPointer<vtkMultiBlockDataSet> curved = CurvedData(buffer.str(), false);
  vtkSmartPointer<vtkMultiBlockDataSet> ignored = CurvedData(buffer.str(), true);
  if (!curved || !ignored)
  {
    std::cerr << "ERROR: the bent patches were not read as expected" << std::endl;
    return EXIT_FAILURE;
  }
  int failures = 0;
  std::vector<double> cpu;
  const Result adaptive = Compare(curved, curved, "adaptive", cpu, 0.0);
  if (!(adaptive.RMS >= 0 && adaptive.RMS <= 3.0))
  {
    std::cerr << "ERROR: curved geometry, adaptive steps: RMS " << adaptive.RMS << std::endl;
    ++failures;
  }
  const Result fixed = Compare(curved, curved, "fixed", cpu, 0.01);
  if (!(fixed.RMS >= 0 && fixed.RMS <= 3.0))
  {
    std::cerr << "ERROR: curved geometry, fixed steps: RMS " << fixed.RMS << std::endl;
    ++failures;
  }
  // The same fixed steps continued over several passes (64 samples each).
  const Result passes = Compare(curved, curved, "passes", cpu, 0.01, 64);
  if (!(passes.RMS >= 0 && passes.RMS <= 3.0) || passes.Passes < 3)
  {
    std::cerr << "ERROR: curved geometry in passes: RMS " << passes.RMS << ", " << passes.Passes
              << " passes" << std::endl;
    ++failures;
  }
  const Result wrong = Compare(ignored, curved, "geometry-ignored", cpu, 0.0);
  if (!(wrong.RMS > 3.0))
  {
    std::cerr << "ERROR: the negative control (geometry ignored) passed: RMS " << wrong.RMS
              << std::endl;
    ++failures;
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
