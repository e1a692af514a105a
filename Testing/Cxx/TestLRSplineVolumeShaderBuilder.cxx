// SPDX-License-Identifier: BSD-3-Clause
// Unit test of vtkLRSplineVolumeShaderBuilder, the shader text of
// vtkLRSplineVolumeMapper without OpenGL (that the sources compile is checked
// by the GL volume tests, which render through the builder):
//  - for every combination of the options that change the text (blend mode,
//    shading and shading model, trimming, sample counting, multi-pass
//    continuation, curved geometry; the degrees, components, vector mode,
//    patch count, lights and supersampling varied along), the fragment source
//    has exactly one #define of each constant with the expected value, after
//    //VTK::System::Dec (where VTK puts the #version), every LR_ constant the
//    shader uses is defined, the shared GLSL is in, and no placeholder is left
//    that VTK's shader cache does not replace;
//  - the vertex, trimming and composite sources have no such placeholder;
//  - negative controls: trimming, blending and multi-pass change the source;
//    a leftover //SV:: placeholder and a template without
//    //VTK::System::Dec are caught by the checks.
#include "vtkLRSplineVolumeShaderBuilder.h"

#include "SplineVizTestUtilities.h"

#include "vtkNew.h"

#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using Defines = std::map<std::string, int>;

int Count(const std::string& text, const std::string& what)
{
  int n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
  {
    ++n;
  }
  return n;
}

// The problems of fragment source `fs` for the expected defines (empty: none).
std::vector<std::string> FragmentProblems(const std::string& fs, const Defines& expected)
{
  std::vector<std::string> problems;
  const std::size_t system = fs.find("//VTK::System::Dec");
  if (system == std::string::npos || Count(fs, "//VTK::System::Dec") != 1)
  {
    problems.push_back("//VTK::System::Dec is not there exactly once");
  }
  for (const auto& d : expected)
  {
    const std::string line = "#define " + d.first + " " + std::to_string(d.second) + "\n";
    const std::size_t at = fs.find(line);
    if (at == std::string::npos)
    {
      problems.push_back("no \"" + line.substr(0, line.size() - 1) + "\"");
    }
    else if (system != std::string::npos && at < system)
    {
      problems.push_back(d.first + " is defined before //VTK::System::Dec");
    }
    if (Count(fs, "#define " + d.first + " ") != 1)
    {
      problems.push_back(d.first + " is not defined exactly once");
    }
  }
  // Every LR_ constant the shader uses is defined (by the builder or by the
  // shared code).
  std::set<std::string> used, defined;
  const std::regex token("LR_[A-Z_]+");
  for (auto it = std::sregex_iterator(fs.begin(), fs.end(), token); it != std::sregex_iterator();
       ++it)
  {
    used.insert(it->str());
  }
  const std::regex define("#define (LR_[A-Z_]+)");
  for (auto it = std::sregex_iterator(fs.begin(), fs.end(), define); it != std::sregex_iterator();
       ++it)
  {
    defined.insert((*it)[1].str());
  }
  for (const std::string& u : used)
  {
    if (!defined.count(u))
    {
      problems.push_back(u + " is used but not defined");
    }
  }
  for (const std::string& p : vtkLRSplineVolumeShaderBuilder::GetUnreplacedPlaceholders(fs))
  {
    problems.push_back("placeholder " + p + " left");
  }
  // Independently of the builder's own check: no //SV:: at all, //VTK::
  // only for what the shader cache replaces.
  if (Count(fs, "//SV::") != 0)
  {
    problems.push_back("an //SV:: placeholder is left");
  }
  if (Count(fs, "//VTK::") != Count(fs, "//VTK::System::Dec") + Count(fs, "//VTK::Output::Dec"))
  {
    problems.push_back("a //VTK:: placeholder other than System::Dec and Output::Dec is left");
  }
  // The shared GLSL and the prelude are in.
  if (fs.find("real lrEvaluate(int offset") == std::string::npos ||
    fs.find("#define SV_OUT(T)") == std::string::npos)
  {
    problems.push_back("the shared evaluation code or the prelude is missing");
  }
  return problems;
}

void Report(
  SplineVizTestStatus& status, const std::string& name, const std::vector<std::string>& problems)
{
  for (const std::string& p : problems)
  {
    status.Fail(name + ": " + p, __FILE__, __LINE__);
  }
}
}

int TestLRSplineVolumeShaderBuilder(int, char*[])
{
  SplineVizTestStatus status;
  const int blends[4] = { 0, 1, 2, 5 };
  const int degrees[3][3] = { { 1, 1, 1 }, { 3, 2, 1 }, { 2, 3, 3 } };
  int combinations = 0;
  std::set<std::string> distinct;
  for (int b = 0; b < 4; ++b)
  {
    for (int flags = 0; flags < 64; ++flags, ++combinations)
    {
      const bool shade = flags & 1, fuchs = flags & 2, trim = flags & 4, count = flags & 8,
                 multiPass = flags & 16, curved = flags & 32;
      // The rest varied along with the combination.
      const int* degree = degrees[combinations % 3];
      const int nc = 1 + combinations % 3;
      const int vectorMode = (combinations / 3) % 2 == 0 ? -1 : 0;
      const int vectorComponent = (combinations / 5) % nc;
      const int patches = 1 + (combinations * 7) % 16;
      const int lights = 1 + combinations % 8;
      const int supersampling = 1 + combinations % 6;

      vtkNew<vtkLRSplineVolumeShaderBuilder> builder;
      builder->SetDegree(degree[0], degree[1], degree[2]);
      builder->SetNumberOfComponents(nc);
      builder->SetVectorMode(vectorMode);
      builder->SetVectorComponent(vectorComponent);
      builder->SetNumberOfPatches(patches);
      builder->SetCurved(curved);
      builder->SetBlendMode(blends[b]);
      builder->SetShade(shade);
      builder->SetFuchsShading(fuchs);
      builder->SetTrim(trim);
      builder->SetCountSamples(count);
      builder->SetMultiPass(multiPass);
      builder->SetSupersampling(supersampling);
      builder->SetNumberOfLights(lights);
      const std::string fs = builder->GetFragmentShaderSource();
      SV_CHECK(
        status, fs == builder->BuildFragmentShaderSource(builder->GetFragmentShaderTemplate()));
      distinct.insert(fs);

      // The expected values, written out here (not read from the builder).
      const Defines expected = { { "LR_DU", degree[0] }, { "LR_DV", degree[1] },
        { "LR_DW", degree[2] }, { "LR_NC", nc },
        { "LR_COMPONENT", nc == 1 ? 0 : (vectorMode == 0 ? vectorComponent : -1) },
        { "LR_BLEND", blends[b] }, { "LR_SHADE", shade && !count ? 1 : 0 },
        { "LR_FUCHS", fuchs ? 1 : 0 }, { "LR_TRIM", trim ? 1 : 0 },
        { "LR_SAMPLE_COUNT", count ? 1 : 0 }, { "LR_PATCHES", patches },
        { "LR_CURVED", curved ? 1 : 0 }, { "LR_MULTIPASS", multiPass ? 1 : 0 },
        { "LR_SUPERSAMPLING", blends[b] == 0 ? supersampling : 1 }, { "LR_LIGHTS", lights },
        { "LR_MAX_PATCHES", 16 }, { "LR_ISO", 8 }, { "LR_CLIP_PLANES", 6 } };
      std::ostringstream name;
      name << "blend " << blends[b] << " shade " << shade << " fuchs " << fuchs << " trim " << trim
           << " count " << count << " passes " << multiPass << " curved " << curved;
      Report(status, name.str(), FragmentProblems(fs, expected));
    }
  }
  std::cout << combinations << " option combinations, " << distinct.size()
            << " different fragment sources" << std::endl;
  // No two combinations give the same source.
  SV_CHECK(status, static_cast<int>(distinct.size()) == combinations);

  // The other stages: complete, no placeholder left but the cache's.
  {
    vtkNew<vtkLRSplineVolumeShaderBuilder> builder;
    for (const std::string& source :
      { builder->GetVertexShaderSource(), builder->GetTrimmingFragmentShaderSource(),
        builder->GetCompositeFragmentShaderSource() })
    {
      SV_CHECK(status, source.find("void main()") != std::string::npos);
      SV_CHECK(status, Count(source, "//VTK::System::Dec") == 1);
      SV_CHECK(status, vtkLRSplineVolumeShaderBuilder::GetUnreplacedPlaceholders(source).empty());
    }
    SV_CHECK(status, builder->GetVertexShaderSource().find("lrMCDCMatrix") != std::string::npos);
    // The template: the shared code in, the options not yet.
    const std::string fragmentTemplate = builder->GetFragmentShaderTemplate();
    SV_CHECK(status, fragmentTemplate.find("#define LR_BLEND") == std::string::npos);
    SV_CHECK(status, Count(fragmentTemplate, "//SV::") == 0);
  }

  // Negative controls: the options change the source, and the checks catch
  // a broken one.
  {
    vtkNew<vtkLRSplineVolumeShaderBuilder> builder;
    const std::string plain = builder->GetFragmentShaderSource();
    builder->SetTrim(true);
    const std::string trimmed = builder->GetFragmentShaderSource();
    SV_CHECK(status, trimmed != plain);
    SV_CHECK(status, plain.find("#define LR_TRIM 0\n") != std::string::npos);
    SV_CHECK(status, trimmed.find("#define LR_TRIM 1\n") != std::string::npos);
    builder->SetTrim(false);
    builder->SetBlendMode(5);
    SV_CHECK(status, builder->GetFragmentShaderSource() != plain);
    builder->SetBlendMode(0);
    builder->SetMultiPass(true);
    SV_CHECK(status, builder->GetFragmentShaderSource() != plain);
    builder->SetMultiPass(false);
    SV_CHECK(status, builder->GetFragmentShaderSource() == plain);

    // The defaults' expectations hold for `plain` ...
    const Defines defaults = { { "LR_DU", 1 }, { "LR_DV", 1 }, { "LR_DW", 1 }, { "LR_NC", 1 },
      { "LR_COMPONENT", 0 }, { "LR_BLEND", 0 }, { "LR_SHADE", 0 }, { "LR_FUCHS", 0 },
      { "LR_TRIM", 0 }, { "LR_SAMPLE_COUNT", 0 }, { "LR_PATCHES", 1 }, { "LR_CURVED", 0 },
      { "LR_MULTIPASS", 0 }, { "LR_SUPERSAMPLING", 4 }, { "LR_LIGHTS", 1 },
      { "LR_MAX_PATCHES", 16 }, { "LR_ISO", 8 }, { "LR_CLIP_PLANES", 6 } };
    SV_CHECK(status, FragmentProblems(plain, defaults).empty());
    // ... not for the trimmed source,
    SV_CHECK(status, !FragmentProblems(trimmed, defaults).empty());
    // a leftover placeholder is found (by both checks),
    const std::string leftover = plain + "\n//SV::Forgotten::Dec\n";
    const std::vector<std::string> left =
      vtkLRSplineVolumeShaderBuilder::GetUnreplacedPlaceholders(leftover);
    SV_CHECK(status, left.size() == 1 && left[0] == "//SV::Forgotten::Dec");
    SV_CHECK(status, FragmentProblems(leftover, defaults).size() == 2);
    SV_CHECK(status,
      vtkLRSplineVolumeShaderBuilder::GetUnreplacedPlaceholders("//VTK::Light::Impl").size() == 1);
    // and a template without //VTK::System::Dec gets no defines.
    std::string broken = builder->GetFragmentShaderTemplate();
    broken.replace(broken.find("//VTK::System::Dec"), 18, "// no system");
    const std::vector<std::string> problems =
      FragmentProblems(builder->BuildFragmentShaderSource(broken), defaults);
    SV_CHECK(status, problems.size() > defaults.size());
    std::cout << "negative controls: " << left.size() << " placeholder left found; "
              << problems.size() << " problems of a template without //VTK::System::Dec"
              << std::endl;
  }

  // PrintSelf.
  {
    vtkNew<vtkLRSplineVolumeShaderBuilder> builder;
    std::ostringstream os;
    builder->Print(os);
    SV_CHECK(status, os.str().find("NumberOfLights: 1") != std::string::npos);
  }
  return status.Result();
}
