// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLRSplineVolumeShaderBuilder.h"

#include "vtkObjectFactory.h"
#include "vtkShaderProgram.h"

#include "vtkLRSplineVolumeCompositeFS.h"
#include "vtkLRSplineVolumeFS.h"
#include "vtkLRSplineVolumeShared.h"
#include "vtkLRSplineVolumeTrimFS.h"
#include "vtkLRSplineVolumeVS.h"
#include "vtkSplineVizShaderPrelude.h"

#include <cctype>
#include <sstream>

vtkStandardNewMacro(vtkLRSplineVolumeShaderBuilder);

namespace
{
// The blend modes the fragment stage knows (vtkLRSplineVolumeMapper's).
constexpr int CompositeBlend = 0;
}

//------------------------------------------------------------------------------
std::string vtkLRSplineVolumeShaderBuilder::GetVertexShaderSource()
{
  return vtkLRSplineVolumeVS;
}

//------------------------------------------------------------------------------
std::string vtkLRSplineVolumeShaderBuilder::GetFragmentShaderTemplate()
{
  std::string fs = vtkLRSplineVolumeFS;
  vtkShaderProgram::Substitute(fs, "//SV::Prelude::Dec", vtkSplineVizShaderPrelude::Get());
  vtkShaderProgram::Substitute(fs, "//SV::LRSplineVolumeShared::Dec", vtkLRSplineVolumeShared);
  return fs;
}

//------------------------------------------------------------------------------
std::string vtkLRSplineVolumeShaderBuilder::BuildFragmentShaderSource(
  const std::string& fragmentTemplate)
{
  // The component the shader evaluates: a scalar field's only one, else
  // VectorComponent or (-1) the magnitude.
  const int component =
    this->NumberOfComponents == 1 ? 0 : (this->VectorMode == 0 ? this->VectorComponent : -1);
  // (System::Dec stays first: VTK's shader cache puts the #version there.)
  std::ostringstream defines;
  defines << "//VTK::System::Dec\n"
          << "#define LR_DU " << this->Degree[0] << "\n#define LR_DV " << this->Degree[1]
          << "\n#define LR_DW " << this->Degree[2] << "\n#define LR_NC " << this->NumberOfComponents
          << "\n#define LR_COMPONENT " << component << "\n#define LR_BLEND " << this->BlendMode
          << "\n#define LR_SHADE " << (this->Shade && !this->CountSamples ? 1 : 0)
          << "\n#define LR_FUCHS " << (this->FuchsShading ? 1 : 0) << "\n#define LR_TRIM "
          << (this->Trim ? 1 : 0) << "\n#define LR_SAMPLE_COUNT " << (this->CountSamples ? 1 : 0)
          << "\n#define LR_PATCHES " << this->NumberOfPatches << "\n#define LR_CURVED "
          << (this->Curved ? 1 : 0) << "\n#define LR_MULTIPASS " << (this->MultiPass ? 1 : 0)
          << "\n#define LR_SUPERSAMPLING "
          << (this->BlendMode == CompositeBlend ? this->Supersampling : 1) << "\n#define LR_LIGHTS "
          << this->NumberOfLights << "\n#define LR_MAX_PATCHES " << MaximumPatches
          << "\n#define LR_ISO " << MaximumIsoValues << "\n#define LR_CLIP_PLANES "
          << MaximumClipPlanes << "\n";
  std::string fs = fragmentTemplate;
  vtkShaderProgram::Substitute(fs, "//VTK::System::Dec", defines.str());
  return fs;
}

//------------------------------------------------------------------------------
std::string vtkLRSplineVolumeShaderBuilder::GetFragmentShaderSource()
{
  return this->BuildFragmentShaderSource(this->GetFragmentShaderTemplate());
}

//------------------------------------------------------------------------------
std::string vtkLRSplineVolumeShaderBuilder::GetTrimmingFragmentShaderSource()
{
  return vtkLRSplineVolumeTrimFS;
}

//------------------------------------------------------------------------------
std::string vtkLRSplineVolumeShaderBuilder::GetCompositeFragmentShaderSource()
{
  return vtkLRSplineVolumeCompositeFS;
}

//------------------------------------------------------------------------------
std::vector<std::string> vtkLRSplineVolumeShaderBuilder::GetUnreplacedPlaceholders(
  const std::string& source)
{
  // Replaced by vtkOpenGLShaderCache::ReadyShaderProgram (the #version and
  // precision, the fragment outputs).
  const char* const cached[] = { "//VTK::System::Dec", "//VTK::Output::Dec" };
  std::vector<std::string> left;
  for (const char* prefix : { "//SV::", "//VTK::" })
  {
    for (std::size_t at = source.find(prefix); at != std::string::npos;
         at = source.find(prefix, at + 1))
    {
      std::size_t end = at + 2;
      while (end < source.size() &&
        (std::isalnum(static_cast<unsigned char>(source[end])) || source[end] == ':' ||
          source[end] == '_'))
      {
        ++end;
      }
      const std::string name = source.substr(at, end - at);
      bool known = false;
      for (const char* c : cached)
      {
        known = known || name == c;
      }
      if (!known)
      {
        left.push_back(name);
      }
    }
  }
  return left;
}

//------------------------------------------------------------------------------
void vtkLRSplineVolumeShaderBuilder::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Degree: " << this->Degree[0] << " " << this->Degree[1] << " " << this->Degree[2]
     << "\n";
  os << indent << "NumberOfComponents: " << this->NumberOfComponents << "\n";
  os << indent << "VectorMode: " << this->VectorMode << "\n";
  os << indent << "VectorComponent: " << this->VectorComponent << "\n";
  os << indent << "NumberOfPatches: " << this->NumberOfPatches << "\n";
  os << indent << "Curved: " << this->Curved << "\n";
  os << indent << "BlendMode: " << this->BlendMode << "\n";
  os << indent << "Shade: " << this->Shade << "\n";
  os << indent << "FuchsShading: " << this->FuchsShading << "\n";
  os << indent << "Trim: " << this->Trim << "\n";
  os << indent << "CountSamples: " << this->CountSamples << "\n";
  os << indent << "MultiPass: " << this->MultiPass << "\n";
  os << indent << "Supersampling: " << this->Supersampling << "\n";
  os << indent << "NumberOfLights: " << this->NumberOfLights << "\n";
}
