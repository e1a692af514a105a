// SPDX-License-Identifier: BSD-3-Clause
#include "vtkPVRenderViewWithLineDepthCues.h"

#include "vtkLineAmbientOcclusionPass.h"
#include "vtkObjectFactory.h"
#include "vtkPVSynchronizedRenderer.h"

vtkStandardNewMacro(vtkPVRenderViewWithLineDepthCues);

//------------------------------------------------------------------------------
vtkPVRenderViewWithLineDepthCues::vtkPVRenderViewWithLineDepthCues()
  : Pass(vtkSmartPointer<vtkLineAmbientOcclusionPass>::New())
{
  this->UpdatePass();
}

//------------------------------------------------------------------------------
vtkPVRenderViewWithLineDepthCues::~vtkPVRenderViewWithLineDepthCues() = default;

//------------------------------------------------------------------------------
void vtkPVRenderViewWithLineDepthCues::SetLineDepthCuesPass(vtkLineAmbientOcclusionPass* pass)
{
  if (pass && pass != this->Pass)
  {
    this->Pass = pass;
    this->UpdatePass();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkLineAmbientOcclusionPass* vtkPVRenderViewWithLineDepthCues::GetLineDepthCuesPass()
{
  return this->Pass;
}

//------------------------------------------------------------------------------
void vtkPVRenderViewWithLineDepthCues::SetUseLineDepthCues(bool use)
{
  if (use != this->UseLineDepthCues)
  {
    this->UseLineDepthCues = use;
    this->UpdatePass();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkPVRenderViewWithLineDepthCues::UpdatePass()
{
  // The pass reads the composited depth (client-server and parallel runs).
  this->SynchronizedRenderers->SetImageProcessingPass(
    this->UseLineDepthCues ? this->Pass.GetPointer() : nullptr);
  this->SynchronizedRenderers->SetUseDepthBuffer(this->UseLineDepthCues);
}

//------------------------------------------------------------------------------
void vtkPVRenderViewWithLineDepthCues::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "UseLineDepthCues: " << this->UseLineDepthCues << "\n";
  os << indent << "LineDepthCuesPass: " << this->Pass.GetPointer() << "\n";
}
