// SPDX-License-Identifier: BSD-3-Clause
#include "vtkStylizedLineRepresentation.h"

#include "vtkObjectFactory.h"
#include "vtkStylizedLineMapper.h"

#include <cstring>

vtkStandardNewMacro(vtkStylizedLineRepresentation);

namespace
{
/// Apply `set` to the full-resolution and the LOD mapper.
template <typename Set>
void Forward(vtkMapper* mapper, vtkMapper* lod, Set set)
{
  set(static_cast<vtkStylizedLineMapper*>(mapper));
  set(static_cast<vtkStylizedLineMapper*>(lod));
}
}

// A setter forwarded to both mappers.
#define vtkStylizedLineForward(method, type)                                                       \
  void vtkStylizedLineRepresentation::method(type value)                                           \
  {                                                                                                \
    Forward(                                                                                       \
      this->Mapper, this->LODMapper, [value](vtkStylizedLineMapper* m) { m->method(value); });     \
    this->Modified();                                                                              \
  }

//------------------------------------------------------------------------------
vtkStylizedLineRepresentation::vtkStylizedLineRepresentation()
{
  this->SetTubeMappers(vtkStylizedLineMapper::New(), vtkStylizedLineMapper::New());
}

//------------------------------------------------------------------------------
vtkStylizedLineRepresentation::~vtkStylizedLineRepresentation() = default;

// clang-format off
vtkStylizedLineForward(SetHaloWidth, double)
vtkStylizedLineForward(SetHaloColorFromBackground, bool)
vtkStylizedLineForward(SetHaloDepthOffset, double)
vtkStylizedLineForward(SetDepthDependentHalo, bool)
vtkStylizedLineForward(SetHaloDepthRange, double)
vtkStylizedLineForward(SetExactSilhouette, bool)
vtkStylizedLineForward(SetDepthCorrection, bool)
vtkStylizedLineForward(SetFixUp, bool)
vtkStylizedLineForward(SetFixUpEpsilon, double)
vtkStylizedLineForward(SetFixUpSides, int)
vtkStylizedLineForward(SetCapping, bool)
vtkStylizedLineForward(SetTexturePattern, int)
vtkStylizedLineForward(SetTextureRepeat, double)
vtkStylizedLineForward(SetTextureRepeatUnits, int)
vtkStylizedLineForward(SetTextureCircumferentialRepeat, int)
vtkStylizedLineForward(SetNormalMapping, bool)
vtkStylizedLineForward(SetShadows, bool)
  // clang-format on

  //------------------------------------------------------------------------------
  void vtkStylizedLineRepresentation::SetHaloColor(double r, double g, double b)
{
  Forward(this->Mapper, this->LODMapper,
    [r, g, b](vtkStylizedLineMapper* m) { m->SetHaloColor(r, g, b); });
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkStylizedLineRepresentation::SetOrientationArray(const char* name)
{
  if (name && (name[0] == '\0' || std::strcmp(name, "None") == 0))
  {
    name = nullptr;
  }
  Forward(this->Mapper, this->LODMapper,
    [name](vtkStylizedLineMapper* m) { m->SetOrientationArray(name); });
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkStylizedLineRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
