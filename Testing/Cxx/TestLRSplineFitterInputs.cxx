// SPDX-License-Identifier: BSD-3-Clause
// vtkLRSplineFitter on the data sets a simulation gives, checked against
// analytic fields (a linear field is in every spline space, so it must be
// reproduced to rounding wherever the data sits):
//  - a tetrahedral mesh (an image cut into tetrahedra) with cell data: the
//    fit at the cell centres (computed here as the mean of the cell's
//    points) reproduces the field; negative control: at the cells' first
//    points it does not match the cell values;
//  - a composite data set of two blocks: one patch fitted to both blocks'
//    points (their count), the field reproduced on both;
//  - a vector array: COMPONENTS gives a 3-component spline reproducing the
//    vectors, MAGNITUDE a scalar one reproducing their length;
//  - the .lr file read back by vtkLRSplineReader with PhysicalBounds = the
//    fitted domain evaluates like the output;
//  - the output's point array has the input array's name, or FieldName's;
//  - output port 1: the mesh's boundary surface, closed (no boundary or
//    non-manifold edges) with the mesh's bounds; empty for a point cloud;
//  - the spline carries that surface (vtkLRSplineField::TRIMMING_SURFACE)
//    and vtkLRSplineVolumeMapper trims by it unconnected; controls: not with
//    TrimByDataBoundary off, not with ExtractBoundary off, not for a point
//    cloud, and a connected surface wins;
//  - pieces split the elements.
#include "vtkLRSplineField.h"
#include "vtkLRSplineFitter.h"
#include "vtkLRSplineReader.h"
#include "vtkLRSplineVolumeMapper.h"

#include "LRSplineFitTestImages.h"
#include "SplineVizTestUtilities.h"

#include "vtkCellData.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkDoubleArray.h"
#include "vtkFeatureEdges.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSphereSource.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnstructuredGrid.h"

#include <iostream>

namespace
{
using FitRun = fittest::FitRunT<vtkLRSplineFitter>;
const std::string OutDir = SPLINEVIZ_TEST_OUTPUT_DIR;

double Linear(const double x[3])
{
  return 1.5 + 2 * x[0] - x[1] + 0.5 * x[2];
}

// A tetrahedral mesh of an image's box; cell data "f" = Linear at the cell
// centres, point data "v" = (x, 2y, -z).
vtkSmartPointer<vtkUnstructuredGrid> TetMesh(const double origin[3])
{
  const int dims[3] = { 7, 6, 5 };
  const double spacing[3] = { 0.4, 0.5, 0.3 };
  auto image = fittest::MakeImage(dims, spacing, origin, Linear, "unused");
  vtkNew<vtkDataSetTriangleFilter> tets;
  tets->SetInputData(image);
  tets->Update();
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->ShallowCopy(tets->GetOutput());
  grid->GetPointData()->Initialize();
  vtkNew<vtkDoubleArray> f;
  f->SetName("f");
  f->SetNumberOfTuples(grid->GetNumberOfCells());
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    grid->GetCellPoints(c, ids);
    double centre[3] = { 0, 0, 0 };
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      double x[3];
      grid->GetPoint(ids->GetId(k), x);
      for (int d = 0; d < 3; ++d)
      {
        centre[d] += x[d] / ids->GetNumberOfIds();
      }
    }
    f->SetValue(c, Linear(centre));
  }
  grid->GetCellData()->AddArray(f);
  vtkNew<vtkDoubleArray> v;
  v->SetName("v");
  v->SetNumberOfComponents(3);
  v->SetNumberOfTuples(grid->GetNumberOfPoints());
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
  {
    double x[3];
    grid->GetPoint(i, x);
    v->SetTuple3(i, x[0], 2 * x[1], -x[2]);
  }
  grid->GetPointData()->AddArray(v);
  return grid;
}

// Largest |spline - Linear| at the cell centres (mean of the points) or, for
// the negative control, at each cell's first point.
double CellError(vtkDataObject* spline, vtkUnstructuredGrid* grid, bool firstPoint)
{
  vtkLRSplineField field;
  std::string error;
  if (!field.Build(spline, nullptr, 2, nullptr, false, &error))
  {
    return 1e300;
  }
  vtkDataArray* f = grid->GetCellData()->GetArray("f");
  vtkNew<vtkIdList> ids;
  double worst = 0.0;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    grid->GetCellPoints(c, ids);
    double x[3] = { 0, 0, 0 };
    const vtkIdType n = firstPoint ? 1 : ids->GetNumberOfIds();
    for (vtkIdType k = 0; k < n; ++k)
    {
      double p[3];
      grid->GetPoint(ids->GetId(k), p);
      for (int d = 0; d < 3; ++d)
      {
        x[d] += p[d] / n;
      }
    }
    double s = 0.0;
    if (field.Evaluate(x, &s, nullptr) < 0)
    {
      return 1e300;
    }
    worst = std::max(worst, std::abs(s - f->GetTuple1(c)));
  }
  return worst;
}

// Largest difference between the output and the vector field (x, 2y, -z) (or its length).
double VectorError(vtkDataObject* spline, vtkUnstructuredGrid* grid, bool magnitude)
{
  vtkLRSplineField field;
  std::string error;
  if (!field.Build(spline, nullptr, 2, nullptr, false, &error))
  {
    return 1e300;
  }
  double worst = 0.0;
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
  {
    double x[3], s[3] = { 0, 0, 0 };
    grid->GetPoint(i, x);
    if (field.Evaluate(x, s, nullptr) < 0)
    {
      return 1e300;
    }
    const double v[3] = { x[0], 2 * x[1], -x[2] };
    if (magnitude)
    {
      worst = std::max(worst, std::abs(s[0] - std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2])));
    }
    else
    {
      for (int c = 0; c < 3; ++c)
      {
        worst = std::max(worst, std::abs(s[c] - v[c]));
      }
    }
  }
  return worst;
}
}

int TestLRSplineFitterInputs(int, char*[])
{
  SplineVizTestStatus status;
  const double origin[3] = { -1, 0.5, 2 };
  auto mesh = TetMesh(origin);

  // 1. Cell data on tetrahedra, the boundary surface, the .lr file.
  {
    FitRun run;
    const std::string file = OutDir + "/TestLRSplineFitterInputs.lr";
    run.Fitter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "f");
    run.Fitter->SetToleranceModeToAbsolute();
    run.Fitter->SetTolerance(1e-9);
    run.Fitter->SetFileName(file.c_str());
    // the domain must hold the mesh's points too (the negative control);
    // functions that see little data are not pulled to the previous fit
    run.Fitter->SetMargin(0.25);
    run.Fitter->SetRegularization(0.0);
    SV_CHECK_MSG(status, run.Run(mesh), run.Error());
    const double error = CellError(run.Output(), mesh, false);
    const double control = CellError(run.Output(), mesh, true);
    std::cout << "tetrahedra, cell data: " << run.Fitter->GetNumberOfDataPoints() << " centres, "
              << run.Fitter->GetNumberOfElements() << " elements, error " << error
              << ", at the first points " << control << std::endl;
    SV_CHECK(status, run.Fitter->GetNumberOfDataPoints() == mesh->GetNumberOfCells());
    SV_CHECK_MSG(status, error <= 1e-9, error);
    SV_CHECK_MSG(status, control > 1e-2, "negative control: " << control);

    vtkPolyData* boundary = vtkPolyData::SafeDownCast(run.Fitter->GetOutputDataObject(1));
    SV_CHECK(status, boundary && boundary->GetNumberOfPolys() > 0);
    if (boundary && boundary->GetNumberOfPolys() > 0)
    {
      vtkNew<vtkFeatureEdges> edges;
      edges->SetInputData(boundary);
      edges->BoundaryEdgesOn();
      edges->NonManifoldEdgesOn();
      edges->FeatureEdgesOff();
      edges->ManifoldEdgesOff();
      edges->Update();
      const double* b = boundary->GetBounds();
      const double* m = mesh->GetBounds();
      double off = 0.0;
      for (int k = 0; k < 6; ++k)
      {
        off = std::max(off, std::abs(b[k] - m[k]));
      }
      std::cout << "boundary: " << boundary->GetNumberOfPolys() << " triangles, "
                << edges->GetOutput()->GetNumberOfLines() << " open edges, bounds off by " << off
                << std::endl;
      SV_CHECK(status, edges->GetOutput()->GetNumberOfLines() == 0);
      SV_CHECK(status, off == 0.0);

      // The spline carries the same surface, which the volume mapper trims by.
      vtkPolyData* carried = vtkLRSplineField::GetTrimmingSurface(run.Output());
      SV_CHECK(status, carried && carried != boundary);
      if (carried)
      {
        SV_CHECK(status, carried->GetNumberOfPolys() == boundary->GetNumberOfPolys());
        SV_CHECK(status, carried->GetPoints()->GetData() == boundary->GetPoints()->GetData());
      }
      vtkNew<vtkLRSplineVolumeMapper> mapper;
      mapper->SetInputConnection(run.Fitter->GetOutputPort(0));
      mapper->Update();
      SV_CHECK(status, mapper->GetTrimmingSurface() == carried);
      mapper->TrimByDataBoundaryOff();
      SV_CHECK(status, mapper->GetTrimmingSurface() == nullptr);
      mapper->TrimByDataBoundaryOn();
      vtkNew<vtkSphereSource> sphere;
      mapper->SetTrimmingSurfaceConnection(sphere->GetOutputPort());
      SV_CHECK(status, mapper->GetTrimmingSurface() == sphere->GetOutput());
    }
    // Without the boundary, nothing to trim by.
    run.Fitter->ExtractBoundaryOff();
    run.Fitter->SetFileName(nullptr);
    SV_CHECK_MSG(status, run.Run(mesh), run.Error());
    SV_CHECK(status, !vtkLRSplineField::GetTrimmingSurface(run.Output()));

    // The output's point array: the input array's name, or OutputFieldName.
    auto outputArray = [&run](const char* name) -> vtkDataArray*
    {
      vtkDataSet* block = vtkDataSet::SafeDownCast(run.Output()->GetBlock(0));
      return block ? block->GetPointData()->GetArray(name) : nullptr;
    };
    SV_CHECK(status, outputArray("f") != nullptr);
    run.Fitter->SetOutputFieldName("renamed");
    SV_CHECK_MSG(status, run.Run(mesh), run.Error());
    SV_CHECK(status, outputArray("renamed") != nullptr && outputArray("f") == nullptr);
    run.Fitter->SetOutputFieldName(nullptr);

    // The file read back in the fitted domain.
    vtkNew<vtkLRSplineReader> reader;
    reader->SetFileName(file.c_str());
    const double* domain = run.Fitter->GetDomain();
    reader->SetPhysicalBounds(domain[0], domain[1], domain[2], domain[3], domain[4], domain[5]);
    reader->Update();
    const double fileError = CellError(reader->GetOutput(), mesh, false);
    std::cout << ".lr read back: error " << fileError << std::endl;
    SV_CHECK_MSG(status, fileError <= 1e-9, fileError);

    // Pieces split the elements.
    run.Fitter->UpdatePiece(1, 3, 0);
    auto* piece = vtkUnstructuredGrid::SafeDownCast(run.Output()->GetBlock(0));
    const vtkIdType all = run.Fitter->GetNumberOfElements();
    SV_CHECK(status, piece && piece->GetNumberOfCells() == all * 2 / 3 - all / 3);
  }

  // 2. A composite data set: both blocks in one patch.
  {
    const double shifted[3] = { origin[0] + 2.4, origin[1], origin[2] };
    auto other = TetMesh(shifted);
    vtkNew<vtkMultiBlockDataSet> blocks;
    blocks->SetBlock(0, mesh);
    blocks->SetBlock(1, other);
    FitRun run;
    run.Fitter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "f");
    run.Fitter->SetToleranceModeToAbsolute();
    run.Fitter->SetTolerance(1e-9);
    SV_CHECK_MSG(status, run.Run(blocks), run.Error());
    const double error =
      std::max(CellError(run.Output(), mesh, false), CellError(run.Output(), other, false));
    std::cout << "composite: " << run.Fitter->GetNumberOfDataPoints() << " points in "
              << run.Output()->GetNumberOfBlocks() << " patch, error " << error << std::endl;
    SV_CHECK(status, run.Output()->GetNumberOfBlocks() == 1);
    SV_CHECK(status,
      run.Fitter->GetNumberOfDataPoints() == mesh->GetNumberOfCells() + other->GetNumberOfCells());
    SV_CHECK_MSG(status, error <= 1e-9, error);
  }

  // 3. A vector array: components and magnitude.
  for (int magnitude = 0; magnitude <= 1; ++magnitude)
  {
    FitRun run;
    run.Fitter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "v");
    run.Fitter->SetVectorMode(
      magnitude ? vtkLRSplineFitter::MAGNITUDE : vtkLRSplineFitter::COMPONENTS);
    run.Fitter->SetToleranceModeToAbsolute();
    run.Fitter->SetTolerance(magnitude ? 1e-3 : 1e-9);
    // 210 points on a 7 x 6 x 5 grid: 4 functions per direction at most
    run.Fitter->SetInitialNumberOfElements(2, 2, 2);
    SV_CHECK_MSG(status, run.Run(mesh), run.Error());
    auto* grid = vtkUnstructuredGrid::SafeDownCast(run.Output()->GetBlock(0));
    vtkDataArray* coefficients = grid ? grid->GetPointData()->GetArray("v") : nullptr;
    const double error = VectorError(run.Output(), mesh, magnitude != 0);
    std::cout << (magnitude ? "magnitude" : "components") << ": "
              << (coefficients ? coefficients->GetNumberOfComponents() : 0) << " components, error "
              << error << ", " << run.Fitter->GetNumberOfElements() << " elements" << std::endl;
    SV_CHECK(status, coefficients && coefficients->GetNumberOfComponents() == (magnitude ? 1 : 3));
    SV_CHECK_MSG(status, error <= (magnitude ? 1e-3 : 1e-9) * (1 + 1e-9), error);
  }

  // 4. Fewer points than the initial spline has functions (5 samples for 6
  // quadratics in z): the refinement stops where the elements hold fewer
  // than 2 points, with a warning, instead of refining without data.
  {
    FitRun run;
    run.Fitter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "v");
    run.Fitter->SetToleranceModeToAbsolute();
    run.Fitter->SetTolerance(1e-9);
    SV_CHECK_MSG(status, run.Run(mesh), run.Error());
    std::cout << "sparse data: " << run.Fitter->GetNumberOfElements() << " elements, "
              << run.Fitter->GetNumberOfIterations() << " fits, met "
              << run.Fitter->GetToleranceMet() << ", " << run.Fitter->GetFitTime() << " s"
              << std::endl;
    SV_CHECK(status, run.Fitter->GetToleranceMet() || run.Warned());
    SV_CHECK(status, run.Fitter->GetNumberOfElements() <= 4096);
  }

  // 5. A point cloud has no boundary surface.
  {
    vtkNew<vtkPolyData> cloud;
    cloud->SetPoints(mesh->GetPoints());
    cloud->GetPointData()->SetScalars(mesh->GetPointData()->GetArray("v"));
    FitRun run;
    run.Fitter->SetToleranceModeToAbsolute();
    run.Fitter->SetTolerance(1e-3);
    SV_CHECK_MSG(status, run.Run(cloud), run.Error());
    vtkPolyData* boundary = vtkPolyData::SafeDownCast(run.Fitter->GetOutputDataObject(1));
    SV_CHECK(status, boundary && boundary->GetNumberOfCells() == 0);
    SV_CHECK(status, !vtkLRSplineField::GetTrimmingSurface(run.Output()));
  }
  return status.Result();
}
