// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkPVRenderViewWithLineDepthCues
 * @brief   ParaView's render view with the line depth cues of
 * vtkLineAmbientOcclusionPass: screen-space ambient occlusion and
 * depth-dependent halos for dense lines and tubes.
 *
 * The view "Render View (Line Depth Cues)" of the SplineViz plugin. It is
 * ParaView's render view with a vtkLineAmbientOcclusionPass as the image
 * processing pass of its synchronized renderers (the way ParaView's Eye Dome
 * Lighting view installs its pass), so the cues apply to everything the view
 * draws: the line representations (Ray-Cast Tubes, Tessellated Tubes,
 * Stylized Lines) and ordinary surfaces. The pass is a sub-proxy of the
 * view: its properties (ambient occlusion radius, levels, samples, strength,
 * bias; halo width, depth offset and range, color) are the view's. With
 * UseLineDepthCues off the view draws exactly as ParaView's render view.
 *
 * The pass reads the depth buffer of the composited image; in client-server
 * mode the view asks its synchronized renderers for the depth buffer too.
 * The cues are Eichelbaum et al.'s LineAO (2013) in screen space and Everts
 * et al.'s depth-dependent halos (2009); see vtkLineAmbientOcclusionPass
 * and docs/line-rendering.md ("Depth cues").
 */
#ifndef vtkPVRenderViewWithLineDepthCues_h
#define vtkPVRenderViewWithLineDepthCues_h

#include "SplineVizParaViewModule.h" // for export macro
#include "vtkPVRenderView.h"
#include "vtkSmartPointer.h" // for vtkSmartPointer

class vtkLineAmbientOcclusionPass;

class SPLINEVIZPARAVIEW_EXPORT vtkPVRenderViewWithLineDepthCues : public vtkPVRenderView
{
public:
  static vtkPVRenderViewWithLineDepthCues* New();
  vtkTypeMacro(vtkPVRenderViewWithLineDepthCues, vtkPVRenderView);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The pass that draws the cues (ParaView sets it from the view proxy's
   * sub-proxy). Default: a pass with its own defaults.
   */
  void SetLineDepthCuesPass(vtkLineAmbientOcclusionPass* pass);
  vtkLineAmbientOcclusionPass* GetLineDepthCuesPass();
  ///@}

  ///@{
  /**
   * Draw the cues. Default on; off, the view draws as ParaView's render view.
   */
  void SetUseLineDepthCues(bool use);
  vtkGetMacro(UseLineDepthCues, bool);
  ///@}

protected:
  vtkPVRenderViewWithLineDepthCues();
  ~vtkPVRenderViewWithLineDepthCues() override;

private:
  vtkPVRenderViewWithLineDepthCues(const vtkPVRenderViewWithLineDepthCues&) = delete;
  void operator=(const vtkPVRenderViewWithLineDepthCues&) = delete;

  /// The pass into the synchronized renderers, or none when off.
  void UpdatePass();

  vtkSmartPointer<vtkLineAmbientOcclusionPass> Pass;
  bool UseLineDepthCues = true;
};

#endif
