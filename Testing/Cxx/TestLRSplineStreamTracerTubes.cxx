// SPDX-License-Identifier: BSD-3-Clause
// Image regression test: streamlines of a real LR spline rendered as tubes.
// Patch 1 of cube-3patch-refined.lr (a real, locally refined quadratic LR
// volume) read in field mode is the linear field v(x, y, z) = (-y, x, z):
// its streamlines are helices about the z axis (circles in x, y; z growing
// like e^t), so the test also checks the traced points against the exact
// solution before rendering. The lines are drawn as ray-cast spline tubes
// (vtkRayCastTubeMapper, radius proportional to "Speed"), coloured by speed,
// inside the outline of the domain.
#include "vtkLRSplineReader.h"
#include "vtkLRSplineStreamTracer.h"

#include "SplineVizTestUtilities.h"

#include "vtkActor.h"
#include "vtkAutoInit.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkLineSource.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkOutlineSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkRayCastTubeMapper.h"

#include <cmath>

// The OpenGL render window (the test executable's automatic initialization
// does not list the rendering backend).
VTK_MODULE_INIT(vtkRenderingOpenGL2);

int TestLRSplineStreamTracerTubes(int argc, char* argv[])
{
  SplineVizTestStatus status;
  vtkNew<vtkLRSplineReader> reader;
  reader->SetFileName(
    (std::string(SPLINEVIZ_EXTERNAL_DATA_DIR) + "/cube-3patch-refined.lr").c_str());
  reader->SetOutputFieldName("velocity");
  reader->Update();
  vtkDataObject* patch1 = reader->GetOutput()->GetBlock(1);
  SV_CHECK(status, patch1 != nullptr);

  vtkNew<vtkLineSource> seeds;
  seeds->SetPoint1(0.2, 0.03, 0.04);
  seeds->SetPoint2(0.95, 0.03, 0.22);
  seeds->SetResolution(15);
  seeds->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);

  vtkNew<vtkLRSplineStreamTracer> tracer;
  tracer->SetInputData(patch1);
  tracer->SetSourceConnection(seeds->GetOutputPort());
  tracer->SetIntegratorType(vtkLRSplineStreamTracer::RUNGE_KUTTA4);
  tracer->SetStepMode(vtkLRSplineStreamTracer::LR_HEURISTIC);
  tracer->SetIntegrationStep(0.5);
  tracer->SetIntegrationDirection(vtkLRSplineStreamTracer::BOTH);
  tracer->Update();
  vtkPolyData* lines = tracer->GetOutput();
  std::cout << lines->GetNumberOfLines() << " lines, " << lines->GetNumberOfPoints() << " points, "
            << tracer->GetNumberOfEvaluations() << " evaluations" << std::endl;
  SV_CHECK(status, lines->GetNumberOfLines() == 32);

  // The exact solution: the radius about the z axis is constant and
  // z = z0 e^t along each line.
  vtkDataArray* time = lines->GetPointData()->GetArray("IntegrationTime");
  vtkDataArray* reason = lines->GetCellData()->GetArray("ReasonForTermination");
  double worst = 0.0;
  vtkCellArray* ca = lines->GetLines();
  vtkIdType n;
  const vtkIdType* ids;
  int c = 0;
  for (ca->InitTraversal(); ca->GetNextCell(n, ids); ++c)
  {
    double p0[3];
    lines->GetPoint(ids[0], p0);
    const double r0 = std::hypot(p0[0], p0[1]);
    for (vtkIdType i = 0; i + 1 < n; ++i) // the last point is Euler-extrapolated to the boundary
    {
      double p[3];
      lines->GetPoint(ids[i], p);
      const double t = time->GetComponent(ids[i], 0);
      worst = std::max(worst, std::abs(std::hypot(p[0], p[1]) - r0));
      worst = std::max(worst, std::abs(p[2] - p0[2] * std::exp(t)));
    }
    SV_CHECK(status, reason->GetComponent(c, 0) == vtkLRSplineStreamTracer::OUT_OF_DOMAIN);
    double last[3];
    lines->GetPoint(ids[n - 1], last);
    const bool onBoundary = last[0] == 0.0 || last[0] == 1.0 || last[1] == 0.0 || last[1] == 1.0 ||
      last[2] == 0.0 || last[2] == 1.0;
    SV_CHECK_MSG(status, onBoundary, "line " << c << " does not end on the boundary");
  }
  std::cout << "largest deviation from the exact helices: " << worst << std::endl;
  SV_CHECK(status, worst < 1e-7);

  double speedRange[2];
  lines->GetPointData()->GetArray("Speed")->GetRange(speedRange);
  vtkNew<vtkRayCastTubeMapper> mapper;
  mapper->SetInputData(lines);
  mapper->SetRadiusArray("Speed");
  mapper->SetRadiusScale(0.018 / speedRange[1]); // the fastest line: radius 0.018
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectColorArray("Speed");
  mapper->SetScalarRange(speedRange);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetSpecular(0.3);
  actor->GetProperty()->SetSpecularPower(30);

  vtkNew<vtkOutlineSource> outline;
  outline->SetBounds(0, 1, 0, 1, 0, 1);
  vtkNew<vtkPolyDataMapper> outlineMapper;
  outlineMapper->SetInputConnection(outline->GetOutputPort());
  vtkNew<vtkActor> outlineActor;
  outlineActor->SetMapper(outlineMapper);
  outlineActor->GetProperty()->SetColor(0.2, 0.2, 0.2);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->AddActor(outlineActor);
  renderer->SetBackground(1, 1, 1);
  renderer->GetActiveCamera()->SetPosition(2.4, -1.6, 1.9);
  renderer->GetActiveCamera()->SetFocalPoint(0.45, 0.45, 0.4);
  renderer->GetActiveCamera()->SetViewUp(0, 0, 1);
  renderer->ResetCamera();
  vtkNew<vtkRenderWindow> window;
  window->SetSize(400, 400);
  window->SetMultiSamples(0);
  window->AddRenderer(renderer);
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
