// SPDX-License-Identifier: BSD-3-Clause
#include "vtkTessellatedTubeRepresentation.h"

#include "vtkObjectFactory.h"
#include "vtkTessellatedTubeMapper.h"

vtkStandardNewMacro(vtkTessellatedTubeRepresentation);

// Forward a setting to the full-resolution and the LOD mapper.
#define vtkTessellatedTubeForward(method, type)                                                    \
  void vtkTessellatedTubeRepresentation::method(type value)                                        \
  {                                                                                                \
    static_cast<vtkTessellatedTubeMapper*>(this->Mapper)->method(value);                           \
    static_cast<vtkTessellatedTubeMapper*>(this->LODMapper)->method(value);                        \
    this->Modified();                                                                              \
  }

//------------------------------------------------------------------------------
vtkTessellatedTubeRepresentation::vtkTessellatedTubeRepresentation()
{
  this->SetTubeMappers(vtkTessellatedTubeMapper::New(), vtkTessellatedTubeMapper::New());
}

//------------------------------------------------------------------------------
vtkTessellatedTubeRepresentation::~vtkTessellatedTubeRepresentation() = default;

vtkTessellatedTubeForward(SetMaxEdgeLength, double) vtkTessellatedTubeForward(
  SetMaxSilhouetteEdgeLength, double) vtkTessellatedTubeForward(SetMaxTessellationLevel, int)
  vtkTessellatedTubeForward(SetMaxSilhouetteTessellationLevel, int)
    vtkTessellatedTubeForward(SetBaseRings, int) vtkTessellatedTubeForward(SetBaseSides, int)
      vtkTessellatedTubeForward(SetLevelOfDetail, bool) vtkTessellatedTubeForward(SetCapping, bool)

  //------------------------------------------------------------------------------
  void vtkTessellatedTubeRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
