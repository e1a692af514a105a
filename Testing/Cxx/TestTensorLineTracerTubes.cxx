// SPDX-License-Identifier: BSD-3-Clause
// Image regression test: tensor lines rendered as ray-cast spline tubes
// (vtkRayCastTubeMapper, radius from the fractional anisotropy, the usual
// DTI direction colors RGB = |e1| from the "DirectionColors" array).
// Left: a twisting helical bundle like Teem's `tend helix`, seeded at every
// second voxel with FA >= 0.5, above a slice of the field's FA. Right: the
// real DIPY small_64D tensors (Testing/Data/DIPY), seeded at every voxel
// with FA >= 0.3, above the b = 0 image's middle slice.
#include "vtkTensorLineTracer.h"

#include "SplineVizTestUtilities.h"
#include "TensorLineTestFields.h"

#include "vtkActor.h"
#include "vtkAutoInit.h"
#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkImageProperty.h"
#include "vtkImageSlice.h"
#include "vtkImageSliceMapper.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRayCastTubeMapper.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkTensorAnalysisFilter.h"
#include "vtkXMLImageDataReader.h"

#include <string>

VTK_MODULE_INIT(vtkRenderingOpenGL2);

using namespace TensorLineTest;

namespace
{
vtkSmartPointer<vtkActor> Tubes(vtkPolyData* lines, double radiusPerFA)
{
  vtkNew<vtkRayCastTubeMapper> mapper;
  mapper->SetInputData(lines);
  mapper->SetRadiusArray("FractionalAnisotropy");
  mapper->SetRadiusScale(radiusPerFA);
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectColorArray("DirectionColors");
  mapper->SetColorModeToDirectScalars();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetSpecular(0.3);
  actor->GetProperty()->SetSpecularPower(30);
  return actor;
}

vtkSmartPointer<vtkImageSlice> Slice(vtkImageData* img, const char* array, int k, double window)
{
  vtkNew<vtkImageSliceMapper> mapper;
  auto copy = vtkSmartPointer<vtkImageData>::New();
  copy->ShallowCopy(img);
  copy->GetPointData()->SetActiveScalars(array);
  mapper->SetInputData(copy);
  mapper->SetOrientationToZ();
  mapper->SetSliceNumber(k);
  auto slice = vtkSmartPointer<vtkImageSlice>::New();
  slice->SetMapper(mapper);
  slice->GetProperty()->SetColorWindow(window);
  slice->GetProperty()->SetColorLevel(window / 2);
  slice->GetProperty()->SetInterpolationTypeToNearest();
  return slice;
}
}

int TestTensorLineTracerTubes(int argc, char* argv[])
{
  SplineVizTestStatus status;

  // The helical bundle.
  TendHelix helix;
  const int dims[3] = { 33, 33, 25 };
  const double origin[3] = { -1.6, -1.6, -1.2 }, spacing[3] = { 0.1, 0.1, 0.1 };
  auto field =
    MakeImage(dims, origin, spacing, [&](const double x[3], double t[6]) { helix.Tensor(x, t); });
  vtkNew<vtkTensorLineTracer> tracer;
  tracer->SetInputData(field);
  tracer->SetSeedMode(vtkTensorLineTracer::SEEDS_FROM_VOXELS);
  tracer->SetSeedStride(2);
  tracer->SetSeedFAThreshold(0.5);
  tracer->SetStoppingFAThreshold(0.3);
  tracer->SetMaximumPropagation(1.0);
  tracer->Update();
  std::cout << "helix: " << tracer->GetOutput()->GetNumberOfLines() << " lines, "
            << tracer->GetOutput()->GetNumberOfPoints() << " points" << std::endl;
  SV_CHECK(status, tracer->GetOutput()->GetNumberOfLines() > 100);
  vtkNew<vtkTensorAnalysisFilter> analysis;
  analysis->SetInputData(field);
  analysis->Update();

  vtkNew<vtkRenderer> left;
  left->SetViewport(0, 0, 0.5, 1);
  left->AddActor(Tubes(tracer->GetOutput(), 0.012));
  left->AddViewProp(
    Slice(vtkImageData::SafeDownCast(analysis->GetOutput()), "FractionalAnisotropy", 2, 1.0));
  left->SetBackground(1, 1, 1);
  left->GetActiveCamera()->SetPosition(3.0, -4.5, 4.0);
  left->GetActiveCamera()->SetFocalPoint(0, 0, -0.2);
  left->GetActiveCamera()->SetViewUp(0, 0, 1);
  left->ResetCamera();
  left->GetActiveCamera()->Zoom(1.3);

  // The real data.
  vtkNew<vtkXMLImageDataReader> reader;
  reader->SetFileName((std::string(SPLINEVIZ_SOURCE_DATA_DIR) + "/DIPY/small_64D_dti.vti").c_str());
  reader->Update();
  vtkNew<vtkTensorLineTracer> real;
  real->SetInputConnection(reader->GetOutputPort());
  real->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "DTI");
  real->SetTensorLayout(2);
  real->SetSeedMode(vtkTensorLineTracer::SEEDS_FROM_VOXELS);
  real->SetSeedFAThreshold(0.3);
  real->SetStoppingFAThreshold(0.15);
  real->SetMinimumLength(4.0);
  real->Update();
  std::cout << "DIPY: " << real->GetOutput()->GetNumberOfLines() << " lines, "
            << real->GetOutput()->GetNumberOfPoints() << " points" << std::endl;
  SV_CHECK(status, real->GetOutput()->GetNumberOfLines() > 300);

  vtkNew<vtkRenderer> right;
  right->SetViewport(0.5, 0, 1, 1);
  right->AddActor(Tubes(real->GetOutput(), 0.12));
  right->AddViewProp(Slice(reader->GetOutput(), "S0", 2, 1200.0));
  right->SetBackground(1, 1, 1);
  right->GetActiveCamera()->SetPosition(40, -30, 40);
  right->GetActiveCamera()->SetFocalPoint(9, 9, 9);
  right->GetActiveCamera()->SetViewUp(0, 0, 1);
  right->ResetCamera();
  right->GetActiveCamera()->Zoom(1.2);

  vtkNew<vtkRenderWindow> window;
  window->SetSize(800, 400);
  window->SetMultiSamples(0);
  window->AddRenderer(left);
  window->AddRenderer(right);
  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(window);
  window->Render();
  const int result = vtkRegressionTestImageThreshold(window, 0.05);
  if (result == vtkRegressionTester::DO_INTERACTOR)
  {
    interactor->Start();
  }
  return (result == vtkRegressionTester::FAILED || status.Result() != 0) ? EXIT_FAILURE
                                                                         : EXIT_SUCCESS;
}
