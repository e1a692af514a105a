// SPDX-License-Identifier: BSD-3-Clause
// vtkLRSplineVolumeMapper against an independent CPU ray caster
// (LRSplineVolumeTestUtilities.h: exact double-precision evaluation with
// vtkLRSplineField, uniform steps ten times finer than the mapper's finest
// step, the transfer functions evaluated directly): RMS difference at most
// 2/255 per channel for composite (unshaded, VTK shading, Fuchs shading),
// maximum intensity and isosurface blending, on the real external file
// (three patches, the field's magnitude and one component) and on a
// generated locally refined scalar volume (non-dyadic knots, several
// levels). Negative controls: the same comparison with a broken shader (no
// opacity correction for the varying step, a wrong element look-up (the
// forest's blocks transposed, the k-d tree's children swapped), a wrong
// Bezier evaluation) must fail the tolerance.
#include "LRSplineVolumeTestUtilities.h"

#include "vtkLRSplineVolumeMapper.h"

#include "vtkColorTransferFunction.h"
#include "vtkObjectFactory.h"
#include "vtkPNGWriter.h"
#include "vtkPiecewiseFunction.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkWindowToImageFilter.h"

#include <cstdio>
#include <iostream>
#include <map>
#include <string>
#include <utility>

namespace
{
// A mapper whose fragment shader has one deliberate mistake.
class BrokenVolumeMapper : public vtkLRSplineVolumeMapper
{
public:
  static BrokenVolumeMapper* New();
  vtkTypeMacro(BrokenVolumeMapper, vtkLRSplineVolumeMapper);
  std::string From, To;

protected:
  std::string GetFragmentShaderSource() override
  {
    std::string fs = this->vtkLRSplineVolumeMapper::GetFragmentShaderSource();
    const std::size_t at = fs.find(this->From);
    if (at == std::string::npos)
    {
      std::cerr << "ERROR: the mutation target \"" << this->From << "\" is not in the shader"
                << std::endl;
      return fs;
    }
    fs.replace(at, this->From.size(), this->To);
    return fs;
  }
};
vtkStandardNewMacro(BrokenVolumeMapper);

struct Scene
{
  std::string Name;
  vtkSmartPointer<vtkMultiBlockDataSet> Data;
  int Blend = 0;
  int Component = -1; // -1 magnitude
  bool Shade = false;
  bool Fuchs = false;
  std::vector<double> Iso;
  double Range[2] = { 0, 1 };
  double Unit = 0.1;
};

void Configure(vtkVolumeProperty* property, const Scene& s)
{
  lrvolume::SetTransferFunctions(property, s.Range[0], s.Range[1]);
  property->SetScalarOpacityUnitDistance(s.Unit);
  property->SetShade(s.Shade ? 1 : 0);
  property->SetAmbient(0.25);
  property->SetDiffuse(0.7);
  property->SetSpecular(0.3);
  property->SetSpecularPower(20.0);
  property->GetIsoSurfaceValues()->SetNumberOfContours(0);
  for (std::size_t i = 0; i < s.Iso.size(); ++i)
  {
    property->GetIsoSurfaceValues()->SetValue(static_cast<int>(i), s.Iso[i]);
  }
}

void WritePNG(vtkRenderWindow* win, const std::string& name)
{
  vtkNew<vtkWindowToImageFilter> w2i;
  w2i->SetInput(win);
  w2i->ReadFrontBufferOff();
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName((std::string(SPLINEVIZ_TEST_OUTPUT_DIR) + "/" + name + ".png").c_str());
  writer->SetInputConnection(w2i->GetOutputPort());
  writer->Write();
}

// Render the scene with `mapper` and with the CPU reference; the RMS
// difference (8-bit units per channel), or -1 on failure.
double Compare(const Scene& s, vtkLRSplineVolumeMapper* mapper, const std::string& tag)
{
  const int width = 120, height = 90;
  const double background[3] = { 0.1, 0.1, 0.12 };
  mapper->SetInputDataObject(s.Data);
  mapper->SetBlendMode(s.Blend);
  mapper->SetVectorMode(
    s.Component < 0 ? vtkLRSplineVolumeMapper::MAGNITUDE : vtkLRSplineVolumeMapper::COMPONENT);
  mapper->SetVectorComponent(std::max(0, s.Component));
  mapper->SetShadingModel(
    s.Fuchs ? vtkLRSplineVolumeMapper::FUCHS : vtkLRSplineVolumeMapper::PHONG);
  vtkNew<vtkVolumeProperty> property;
  Configure(property, s);
  lrvolume::Scene scene(mapper, property, width, height, background);
  scene.SetCamera(nullptr, 35, 25, 1.25);
  vtkVolume* volume = scene.Volume;
  vtkRenderer* ren = scene.Renderer;
  vtkRenderWindow* win = scene.Window;
  win->Render();
  if (!mapper->UpdateSpline() || std::string(mapper->GetLastErrorMessage()) != "")
  {
    std::cerr << "ERROR: " << s.Name << ": " << mapper->GetLastErrorMessage() << std::endl;
    return -1;
  }
  const std::vector<double> gpu = lrvolume::ReadRGB(win);
  WritePNG(win, "TestLRSplineVolumeReference-" + s.Name + tag);

  vtkLRSplineField field;
  std::string error;
  if (!field.Build(s.Data, nullptr, vtkLRSplineElementLocator::KD_FOREST, nullptr, false, &error))
  {
    std::cerr << "ERROR: " << error << std::endl;
    return -1;
  }
  lrvolume::View view;
  view.Set(ren, volume);
  lrvolume::Settings settings;
  settings.BlendMode = s.Blend;
  settings.Component = s.Component;
  settings.Shade = s.Shade;
  settings.Fuchs = s.Fuchs;
  settings.IsoValues = s.Iso;
  const int degree = field.GetMaximumDegree();
  settings.Step = lrvolume::MinimumElementSide(field) / (1 << degree) / 10.0;
  // The reference of a scene is computed once (the negative controls reuse it).
  static std::map<std::string, std::vector<double>> cache;
  std::vector<double>& cpu = cache[s.Name];
  if (cpu.empty())
  {
    cpu = lrvolume::OverBackground(lrvolume::Render(field, volume, view, settings), background);
  }
  const double rms = lrvolume::RMS(gpu, cpu);
  const std::string out = std::string(SPLINEVIZ_TEST_OUTPUT_DIR) + "/TestLRSplineVolumeReference-";
  lrvolume::WritePNG(cpu, width, height, out + s.Name + tag + "-cpu.png");
  lrvolume::WritePNG(gpu, width, height, out + s.Name + tag + "-diff.png", &cpu);
  const long long covered = lrvolume::CountNonBackground(cpu, background);
  std::cout << s.Name << tag << ": RMS " << rms << " / 255 over " << width * height << " pixels ("
            << covered << " not background), CPU step " << settings.Step << std::endl;
  if (covered < width * height / 8)
  {
    std::cerr << "ERROR: " << s.Name << ": the reference covers only " << covered
              << " pixels: the scene does not test much" << std::endl;
    return -1;
  }
  return rms;
}
}

int TestLRSplineVolumeReference(int, char*[])
{
  int failures = 0;
  vtkNew<vtkLRSplineReader> reader;
  reader->SetFileName(SPLINEVIZ_EXTERNAL_DATA_DIR "/cube-3patch-refined.lr");
  reader->Update();
  vtkSmartPointer<vtkMultiBlockDataSet> external = reader->GetOutput();
  vtkIdType generatedElements = 0;
  vtkSmartPointer<vtkMultiBlockDataSet> generated = lrvolume::RefinedScalarVolume(
    std::string(SPLINEVIZ_TEST_OUTPUT_DIR) + "/TestLRSplineVolumeReference.lr", 4,
    &generatedElements);
  if (!external || external->GetNumberOfBlocks() != 3 || !generated)
  {
    std::cerr << "ERROR: could not read the test volumes" << std::endl;
    return 1;
  }
  std::cout << "generated volume: " << generatedElements << " elements" << std::endl;

  std::vector<Scene> scenes;
  {
    Scene s;
    s.Name = "external-composite";
    s.Data = external;
    s.Range[0] = 0.0;
    s.Range[1] = 1.75;
    s.Unit = 0.15;
    scenes.push_back(s);
    s.Name = "external-composite-shaded-component";
    s.Component = 2;
    s.Range[1] = 1.0;
    s.Shade = true;
    scenes.push_back(s);
    s.Name = "external-mip";
    s.Component = -1;
    s.Range[1] = 1.75;
    s.Shade = false;
    s.Blend = 1;
    scenes.push_back(s);
    s.Name = "external-iso";
    s.Blend = 5;
    s.Shade = true;
    s.Iso = { 0.8, 1.3 };
    scenes.push_back(s);
  }
  {
    Scene s;
    s.Name = "generated-composite-fuchs";
    s.Data = generated;
    s.Range[0] = 0.0;
    s.Range[1] = 1.1;
    s.Unit = 0.08;
    s.Shade = true;
    s.Fuchs = true;
    scenes.push_back(s);
    s.Name = "generated-composite";
    s.Shade = false;
    s.Fuchs = false;
    scenes.push_back(s);
    s.Name = "generated-mip";
    s.Blend = 1;
    scenes.push_back(s);
    s.Name = "generated-iso";
    s.Blend = 5;
    s.Shade = true;
    s.Iso = { 0.35, 0.6 };
    scenes.push_back(s);
  }
  const double tolerance = 2.0;
  for (const Scene& s : scenes)
  {
    vtkNew<vtkLRSplineVolumeMapper> mapper;
    const double rms = Compare(s, mapper, "");
    if (rms < 0 || rms > tolerance)
    {
      std::cerr << "ERROR: " << s.Name << ": RMS " << rms << " exceeds " << tolerance << "/255"
                << std::endl;
      ++failures;
    }
  }

  // Negative controls: each broken shader must fail the same tolerance.
  struct Mutation
  {
    std::string Name, From, To;
    int Scene;
  };
  const std::vector<Mutation> mutations = {
    { "no-step-correction", "c.a, ds / lrUnitDistance", "c.a, 0.5", 5 },
    { "no-step-correction", "c.a, ds / lrUnitDistance", "c.a, 0.5", 0 },
    { "wrong-block", "(b[2] * blocks[1] + b[1]) * blocks[0] + b[0]",
      "(b[0] * blocks[1] + b[1]) * blocks[0] + b[2]", 5 },
    { "wrong-element", "u[dir] < lrNodeSplit(nodes + index)",
      "u[dir] >= lrNodeSplit(nodes + index)", 3 },
    { "wrong-bezier", "((k * (dv + 1) + j) * (du + 1))", "((j * (dv + 1) + k) * (du + 1))", 5 },
    { "wrong-bezier", "((k * (dv + 1) + j) * (du + 1))", "((j * (dv + 1) + k) * (du + 1))", 3 },
  };
  for (const Mutation& m : mutations)
  {
    vtkNew<BrokenVolumeMapper> broken;
    broken->From = m.From;
    broken->To = m.To;
    const double rms = Compare(scenes[m.Scene], broken, "-" + m.Name);
    if (rms >= 0 && rms <= tolerance)
    {
      std::cerr << "ERROR: the shader with " << m.Name << " passes on " << scenes[m.Scene].Name
                << " (RMS " << rms << "): the comparison cannot see that mistake" << std::endl;
      ++failures;
    }
    else
    {
      std::cout << "  negative control " << m.Name << " fails as it must" << std::endl;
    }
  }
  return failures == 0 ? 0 : 1;
}
