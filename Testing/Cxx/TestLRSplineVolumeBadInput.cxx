// SPDX-License-Identifier: BSD-3-Clause
// Bad input for vtkLRSplineVolumeMapper: a clear error through vtkErrorMacro
// naming the problem, nothing drawn (the window keeps its background), no
// crash; and a mapper given good input again renders again.
//  - no input; a polygonal data set; a surface (2D) spline (Bezier
//    quadrilaterals) (geometry mode is rendered: TestLRSplineVolumeCurved);
//  - rational data (rational weights); no point-data array; a field name that
//    does not exist; NaN coefficients; a degree above 3; 17 patches; a vector
//    component that does not exist;
//  - an empty transfer function; the isosurface blend mode without iso
//    values; a trimming surface without polygons;
//  - a shader that does not compile.
#include "LRSplineVolumeTestUtilities.h"
#include "SplineVizTestUtilities.h"

#include "vtkLRSplineVolumeMapper.h"

#include "vtkCellType.h"
#include "vtkColorTransferFunction.h"
#include "vtkDoubleArray.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkLogger.h"
#include "vtkStringOutputWindow.h"
#include "vtkTestErrorObserver.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <functional>
#include <limits>

namespace
{
class BrokenShaderMapper : public vtkLRSplineVolumeMapper
{
public:
  static BrokenShaderMapper* New();
  vtkTypeMacro(BrokenShaderMapper, vtkLRSplineVolumeMapper);

protected:
  std::string GetFragmentShaderSource() override
  {
    return this->vtkLRSplineVolumeMapper::GetFragmentShaderSource() + "\nthis is not GLSL;\n";
  }
};
vtkStandardNewMacro(BrokenShaderMapper);

const double Background[3] = { 0.2, 0.3, 0.4 };

vtkSmartPointer<vtkVolumeProperty> GoodProperty()
{
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  vtkNew<vtkColorTransferFunction> ctf;
  ctf->AddRGBPoint(0.0, 1.0, 1.0, 1.0);
  ctf->AddRGBPoint(2.0, 1.0, 0.5, 0.0);
  vtkNew<vtkPiecewiseFunction> otf;
  otf->AddPoint(0.0, 0.5);
  otf->AddPoint(2.0, 1.0);
  property->SetColor(ctf);
  property->SetScalarOpacity(otf);
  return property;
}

struct Outcome
{
  std::string Errors;
  long long Drawn = 0;
};

// Render `input` with `mapper` (configured by `setup`) and the property.
Outcome Render(vtkLRSplineVolumeMapper* mapper, vtkDataObject* input, vtkVolumeProperty* property,
  const std::function<void(vtkLRSplineVolumeMapper*)>& setup = nullptr)
{
  vtkNew<vtkTest::ErrorObserver> observer;
  mapper->AddObserver(vtkCommand::ErrorEvent, observer);
  mapper->AddObserver(vtkCommand::WarningEvent, observer);
  if (input)
  {
    mapper->SetInputDataObject(input);
  }
  if (setup)
  {
    setup(mapper);
  }
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  vtkNew<vtkRenderer> ren;
  ren->SetBackground(Background[0], Background[1], Background[2]);
  ren->AddVolume(volume);
  vtkNew<vtkRenderWindow> win;
  win->SetMultiSamples(0);
  win->SetSize(64, 48);
  win->AddRenderer(ren);
  // A camera that sees the unit cube even when the bounds are unknown.
  ren->GetActiveCamera()->SetFocalPoint(0.5, 0.5, 0.5);
  ren->GetActiveCamera()->SetPosition(0.5, 0.5, 4.0);
  ren->ResetCameraClippingRange(0, 1, 0, 1, 0, 1);
  win->Render();
  win->Render(); // errors are reported once, not per frame
  Outcome o;
  o.Errors = observer->GetErrorMessage() + observer->GetWarningMessage();
  o.Drawn = lrvolume::CountNonBackground(lrvolume::ReadRGB(win), Background);
  mapper->RemoveAllObservers();
  return o;
}

void Expect(SplineVizTestStatus& status, const std::string& name, const Outcome& o,
  const std::string& keyword)
{
  std::cout << name << ": " << o.Drawn << " pixels drawn; "
            << (o.Errors.empty() ? "no error" : o.Errors.substr(0, o.Errors.find('\n')))
            << std::endl;
  SV_CHECK_MSG(status, o.Errors.find(keyword) != std::string::npos,
    name + ": the error does not say \"" + keyword + "\"");
  SV_CHECK_MSG(status, o.Drawn == 0, name + ": something was drawn");
  // One report per problem, not one per frame (two frames were rendered).
  const std::string mark = "vtkLRSplineVolumeMapper.cxx, line";
  const std::size_t first = o.Errors.find(mark);
  SV_CHECK_MSG(status,
    first != std::string::npos && o.Errors.find(mark, first + 1) == std::string::npos,
    name + ": the error is not reported exactly once");
}

// Messages of other objects (VTK's pipeline, the shader compiler) during
// `run`, captured instead of printed (they are expected).
std::string Captured(const std::function<void()>& run)
{
  vtkNew<vtkStringOutputWindow> window;
  vtkSmartPointer<vtkOutputWindow> previous = vtkOutputWindow::GetInstance();
  const vtkLogger::Verbosity verbosity = vtkLogger::GetCurrentVerbosityCutoff();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  vtkOutputWindow::SetInstance(window);
  run();
  vtkOutputWindow::SetInstance(previous);
  vtkLogger::SetStderrVerbosity(verbosity);
  return window->GetOutput();
}

// A shallow copy of the reader's output (blocks copied so they can be changed).
vtkSmartPointer<vtkMultiBlockDataSet> Copy(vtkMultiBlockDataSet* in, bool deep = false)
{
  auto out = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  out->SetNumberOfBlocks(in->GetNumberOfBlocks());
  for (unsigned int b = 0; b < in->GetNumberOfBlocks(); ++b)
  {
    auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
    if (deep)
    {
      grid->DeepCopy(in->GetBlock(b));
    }
    else
    {
      grid->ShallowCopy(in->GetBlock(b));
    }
    out->SetBlock(b, grid);
  }
  return out;
}
}

int TestLRSplineVolumeBadInput(int, char*[])
{
  SplineVizTestStatus status;
  vtkNew<vtkLRSplineReader> reader;
  reader->SetFileName(SPLINEVIZ_EXTERNAL_DATA_DIR "/cube-3patch-refined.lr");
  reader->Update();
  vtkMultiBlockDataSet* good = reader->GetOutput();
  vtkSmartPointer<vtkVolumeProperty> property = GoodProperty();

  // The good case draws (the checks below are meaningful).
  {
    vtkNew<vtkLRSplineVolumeMapper> mapper;
    const Outcome o = Render(mapper, good, property);
    std::cout << "good input: " << o.Drawn << " pixels drawn" << std::endl;
    SV_CHECK(status, o.Drawn > 500 && o.Errors.empty());
  }
  {
    // (VTK's pipeline also says that the required input is not connected.)
    vtkNew<vtkLRSplineVolumeMapper> mapper;
    Outcome o;
    const std::string others = Captured(
      [&]() {
        o =
          Render(mapper, nullptr, property, [](vtkLRSplineVolumeMapper* m) { m->UpdateSpline(); });
      });
    std::cout << "  (VTK: " << others.substr(0, others.find('\n')) << ")" << std::endl;
    Expect(status, "no input", o, "no input");
  }
  {
    vtkNew<vtkLRSplineVolumeMapper> mapper;
    vtkNew<vtkSphereSource> sphere;
    sphere->Update();
    Expect(status, "polygonal input", Render(mapper, sphere->GetOutput(), property), "surface");
  }
  {
    // A surface spline: one biquadratic Bezier quadrilateral.
    vtkNew<vtkUnstructuredGrid> grid;
    vtkNew<vtkPoints> points;
    vtkNew<vtkDoubleArray> field;
    field->SetName("Field");
    std::vector<vtkIdType> ids;
    for (int j = 0; j < 3; ++j)
    {
      for (int i = 0; i < 3; ++i)
      {
        ids.push_back(points->InsertNextPoint(i / 2.0, j / 2.0, 0.0));
        field->InsertNextValue(i + j);
      }
    }
    grid->SetPoints(points);
    grid->InsertNextCell(VTK_BEZIER_QUADRILATERAL, 9, ids.data());
    grid->GetPointData()->SetScalars(field);
    vtkNew<vtkMultiBlockDataSet> mb;
    mb->SetBlock(0, grid);
    vtkNew<vtkLRSplineVolumeMapper> mapper;
    Expect(status, "surface spline", Render(mapper, mb, property), "surface (2D) spline");
  }
  {
    auto data = Copy(good);
    auto* grid = vtkUnstructuredGrid::SafeDownCast(data->GetBlock(1));
    vtkNew<vtkPointData> pd;
    pd->ShallowCopy(grid->GetPointData());
    grid->GetPointData()->ShallowCopy(pd);
    vtkNew<vtkDoubleArray> weights;
    weights->SetName("RationalWeights");
    weights->SetNumberOfTuples(grid->GetNumberOfPoints());
    weights->Fill(1.0);
    grid->GetPointData()->SetRationalWeights(weights);
    vtkNew<vtkLRSplineVolumeMapper> mapper;
    Expect(status, "rational weights", Render(mapper, data, property), "rational");
  }
  {
    auto data = Copy(good);
    vtkUnstructuredGrid::SafeDownCast(data->GetBlock(0))->GetPointData()->Initialize();
    vtkNew<vtkLRSplineVolumeMapper> mapper;
    Expect(status, "no point data", Render(mapper, data, property), "no point-data array");
  }
  {
    vtkNew<vtkLRSplineVolumeMapper> mapper;
    Expect(status, "missing field name",
      Render(mapper, good, property,
        [](vtkLRSplineVolumeMapper* m) { m->SetFieldArray("Temperature"); }),
      "Temperature");
  }
  {
    auto data = Copy(good, true);
    auto* grid = vtkUnstructuredGrid::SafeDownCast(data->GetBlock(2));
    grid->GetPointData()->GetArray(0)->SetComponent(
      grid->GetNumberOfPoints() / 2, 1, std::numeric_limits<double>::quiet_NaN());
    vtkNew<vtkLRSplineVolumeMapper> mapper;
    Expect(status, "NaN coefficient", Render(mapper, data, property), "NaN");
  }
  {
    // Degree 4 in one direction.
    vtkLRSplineBuilder builder;
    const int degree[3] = { 4, 2, 2 };
    const std::vector<double> breaks[3] = { { 0, 0.5, 1 }, { 0, 1 }, { 0, 1 } };
    std::string error;
    SV_CHECK(status, builder.InitializeTensorProduct(degree, breaks, 1, &error));
    builder.SetCoefficientsFromGreville([](const double g[3], double* c) { c[0] = g[0]; });
    const std::string path =
      std::string(SPLINEVIZ_TEST_OUTPUT_DIR) + "/TestLRSplineVolumeBadInput-degree4.lr";
    {
      std::ofstream out(path);
      builder.GetPatch().Write(out);
    }
    vtkNew<vtkLRSplineReader> quartic;
    quartic->SetFileName(path.c_str());
    quartic->Update();
    vtkNew<vtkLRSplineVolumeMapper> mapper;
    Expect(status, "degree 4", Render(mapper, quartic->GetOutput(), property), "degree 4");
  }
  {
    vtkNew<vtkMultiBlockDataSet> many;
    for (unsigned int b = 0; b < 17; ++b)
    {
      many->SetBlock(b, good->GetBlock(b % 3));
    }
    vtkNew<vtkLRSplineVolumeMapper> mapper;
    Expect(status, "17 patches", Render(mapper, many, property), "at most 16");
  }
  {
    // A 2-component field and component 2.
    auto data = Copy(good, true);
    for (unsigned int b = 0; b < 3; ++b)
    {
      auto* grid = vtkUnstructuredGrid::SafeDownCast(data->GetBlock(b));
      vtkDataArray* f = grid->GetPointData()->GetArray(0);
      vtkNew<vtkDoubleArray> two;
      two->SetName("Field2");
      two->SetNumberOfComponents(2);
      two->SetNumberOfTuples(f->GetNumberOfTuples());
      for (vtkIdType i = 0; i < f->GetNumberOfTuples(); ++i)
      {
        two->SetTuple2(i, f->GetComponent(i, 0), f->GetComponent(i, 1));
      }
      grid->GetPointData()->Initialize();
      grid->GetPointData()->AddArray(two);
    }
    vtkNew<vtkLRSplineVolumeMapper> mapper;
    Expect(status, "component 2 of a 2-vector",
      Render(mapper, data, property,
        [](vtkLRSplineVolumeMapper* m)
        {
          m->SetVectorModeToComponent();
          m->SetVectorComponent(2);
        }),
      "VectorComponent 2");
  }
  {
    vtkNew<vtkVolumeProperty> empty;
    vtkNew<vtkPiecewiseFunction> none;
    vtkNew<vtkColorTransferFunction> ctf;
    ctf->AddRGBPoint(0, 1, 1, 1);
    empty->SetColor(ctf);
    empty->SetScalarOpacity(none);
    vtkNew<vtkLRSplineVolumeMapper> mapper;
    Expect(
      status, "empty transfer function", Render(mapper, good, empty), "transfer function is empty");
  }
  {
    vtkNew<vtkVolumeProperty> noIso;
    noIso->DeepCopy(property);
    noIso->GetIsoSurfaceValues()->SetNumberOfContours(0);
    vtkNew<vtkLRSplineVolumeMapper> mapper;
    Expect(status, "isosurface without values",
      Render(
        mapper, good, noIso, [](vtkLRSplineVolumeMapper* m) { m->SetBlendModeToIsoSurface(); }),
      "without iso values");
  }
  {
    vtkNew<vtkPolyData> nothing;
    vtkNew<vtkPoints> pts;
    pts->InsertNextPoint(0, 0, 0);
    nothing->SetPoints(pts);
    vtkNew<vtkLRSplineVolumeMapper> mapper;
    Expect(status, "trimming surface without polygons",
      Render(mapper, good, property,
        [&](vtkLRSplineVolumeMapper* m) { m->SetTrimmingSurfaceData(nothing); }),
      "no polygons");
  }
  {
    vtkNew<BrokenShaderMapper> mapper;
    Outcome o;
    const std::string compiler = Captured([&]() { o = Render(mapper, good, property); });
    Expect(status, "a shader that does not compile", o, "did not compile");
    SV_CHECK_MSG(status, compiler.find("syntax error") != std::string::npos,
      "the compiler's message is not shown");
  }
  // Fixed steps too fine for llvmpipe's loop limit: drawn in several passes
  // (continuation), without a warning; none for adaptive steps either.
  {
    vtkNew<vtkLRSplineVolumeMapper> mapper;
    const Outcome o = Render(mapper, good, property,
      [](vtkLRSplineVolumeMapper* m)
      {
        m->AdaptiveStepsOff();
        m->SetSampleDistance(1e-4);
      });
    std::string renderer = "?";
    {
      // the OpenGL renderer string, through VTK (ReportCapabilities)
      vtkNew<vtkRenderWindow> probe;
      probe->SetSize(8, 8);
      probe->Render();
      if (const char* caps = probe->ReportCapabilities())
      {
        renderer = caps;
        const size_t at = renderer.find("renderer string:");
        renderer = at == std::string::npos ? "?" : renderer.substr(at + 17);
        renderer = renderer.substr(0, renderer.find('\n'));
      }
      probe->Finalize();
    }
    const bool llvmpipe = renderer.find("llvmpipe") != std::string::npos;
    std::cout << "fixed steps of 1e-4 (" << renderer << "): " << o.Drawn << " pixels drawn; "
              << (o.Errors.empty() ? "no warning" : o.Errors) << std::endl;
    SV_CHECK(status, o.Drawn > 500);
    // The rays are continued in further passes: nothing is cut short.
    (void)llvmpipe;
    SV_CHECK_MSG(status, o.Errors.find("cut short") == std::string::npos,
      "a warning that rays are cut short, though they are continued");
    SV_CHECK_MSG(status, mapper->GetNumberOfPasses() > 1, "the fine steps ran in one pass");
    const Outcome adaptive = Render(mapper, good, property,
      [](vtkLRSplineVolumeMapper* m)
      {
        m->AdaptiveStepsOn();
        m->SetSampleDistance(0.0);
      });
    SV_CHECK_MSG(status, adaptive.Errors.empty(), "adaptive steps warned: " << adaptive.Errors);
  }
  // Recovery: a mapper that had bad input renders once the input is good.
  {
    vtkNew<vtkLRSplineVolumeMapper> mapper;
    auto data = Copy(good);
    vtkUnstructuredGrid::SafeDownCast(data->GetBlock(0))->GetPointData()->Initialize();
    Render(mapper, data, property);
    const Outcome o = Render(mapper, good, property);
    std::cout << "recovery: " << o.Drawn << " pixels drawn" << std::endl;
    SV_CHECK(status, o.Drawn > 500 && o.Errors.empty());
  }
  return status.Result();
}
