// SPDX-License-Identifier: BSD-3-Clause
// vtkSuperquadricGlyphMapper with every kind of input, bad input, parameter
// changes, thresholds, masks, scale modes and picking:
//  - the same tensors in vtkImageData, vtkUnstructuredGrid (points only),
//    vtkPolyData and a two-block vtkMultiBlockDataSet, and in every
//    component layout (VTK, NIfTI/DIPY, FSL/MFEM, 9 and Teem's 7 components):
//    identical pictures;
//  - bad input: a missing tensor array, no active tensors, a 3-component
//    array (errors, nothing drawn); NaN, infinite and zero tensors (one
//    warning with the counts, nothing drawn for them, the others drawn);
//  - changing gamma, scale, scale mode, thresholds, sign policy, color mode,
//    roundness, thickness and iterations re-renders without uploading the
//    tensors again (UploadCount), while changing the data uploads once;
//  - FA and minimum-eigenvalue thresholds, the mask array, the normalized
//    and clamped scale modes;
//  - hardware point picking returns input point ids (also with a mask that
//    compacts the uploaded glyphs);
//  - a camera inside a glyph (the sprite crosses the near plane) renders.
#include "vtkSplineVizTensorMath.h"
#include "vtkSuperquadricGlyphMapper.h"

#include "SplineVizTestUtilities.h"
#include "SuperquadricGlyphTestUtilities.h"
#include "TensorTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkHardwareSelector.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSelection.h"
#include "vtkSelectionNode.h"
#include "vtkTestErrorObserver.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <cmath>
#include <limits>
#include <set>
#include <vector>

namespace
{
namespace TM = vtkSplineVizTensorMath;

constexpr int W = 240;
constexpr int H = 180;

struct Scene
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkSuperquadricGlyphMapper> Mapper;
  vtkNew<vtkActor> Actor;

  Scene()
  {
    this->Window->SetSize(W, H);
    this->Window->SetMultiSamples(0);
    this->Window->AddRenderer(this->Renderer);
    this->Renderer->SetBackground(0, 0, 0);
    this->Actor->SetMapper(this->Mapper);
    this->Renderer->AddActor(this->Actor);
    this->Mapper->SetScaleFactor(0.42);
    this->Mapper->SetNegativeEigenvaluePolicy(vtkSuperquadricGlyphMapper::ABSOLUTE_VALUES);
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetFocalPoint(1.5, 1.0, 0.0);
    camera->SetPosition(3.2, -2.6, 4.4);
    camera->SetViewUp(0, 0, 1);
    camera->SetViewAngle(32);
    camera->SetClippingRange(1.0, 12.0);
  }

  /// Renders and returns the RGB pixels.
  std::vector<unsigned char> Render()
  {
    this->Window->Render();
    std::vector<unsigned char> rgb(3 * W * H);
    unsigned char* p = this->Window->GetPixelData(0, 0, W - 1, H - 1, 0);
    std::copy(p, p + 3 * W * H, rgb.begin());
    delete[] p;
    return rgb;
  }
};

int Covered(const std::vector<unsigned char>& rgb)
{
  int n = 0;
  for (size_t i = 0; i < rgb.size(); i += 3)
  {
    n += (rgb[i] | rgb[i + 1] | rgb[i + 2]) != 0;
  }
  return n;
}

/// Pixels whose color differs by more than `tolerance` in some channel.
int Differ(
  const std::vector<unsigned char>& a, const std::vector<unsigned char>& b, int tolerance = 0)
{
  int n = 0;
  for (size_t i = 0; i < a.size(); ++i)
  {
    if (std::abs(int(a[i]) - int(b[i])) > tolerance)
    {
      ++n;
      i += 2 - i % 3; // next pixel
    }
  }
  return n;
}

std::vector<std::array<double, 6>> Tensors()
{
  std::vector<std::array<double, 6>> t;
  for (const auto& h : sqtest::HandTensors())
  {
    t.push_back(sqtest::Compose(h));
  }
  return t;
}

/// Points of the 4 x 3 grid of TensorImage, with the tensors in `layout`.
vtkSmartPointer<vtkPoints> GridPoints(int first, int count)
{
  auto pts = vtkSmartPointer<vtkPoints>::New();
  for (int i = first; i < first + count; ++i)
  {
    pts->InsertNextPoint(i % 4, i / 4, 0.0);
  }
  return pts;
}

vtkSmartPointer<vtkDoubleArray> Encode(
  const std::vector<std::array<double, 6>>& tensors, int layout, int first, int count)
{
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName("T");
  a->SetNumberOfComponents(TM::GetNumberOfComponents(layout));
  for (int i = first; i < first + count; ++i)
  {
    const std::vector<double> c = tensortest::Encode(layout, tensors[i].data());
    a->InsertNextTuple(c.data());
  }
  return a;
}

std::set<vtkIdType> PickPoints(Scene& s, int x0, int y0, int x1, int y1)
{
  vtkNew<vtkHardwareSelector> selector;
  selector->SetRenderer(s.Renderer);
  selector->SetArea(x0, y0, x1, y1);
  selector->SetFieldAssociation(vtkDataObject::FIELD_ASSOCIATION_POINTS);
  vtkSmartPointer<vtkSelection> selection = vtk::TakeSmartPointer(selector->Select());
  std::set<vtkIdType> ids;
  for (unsigned int n = 0; selection && n < selection->GetNumberOfNodes(); ++n)
  {
    vtkIdTypeArray* list = vtkIdTypeArray::SafeDownCast(selection->GetNode(n)->GetSelectionList());
    for (vtkIdType k = 0; list && k < list->GetNumberOfTuples(); ++k)
    {
      ids.insert(list->GetValue(k));
    }
  }
  return ids;
}

/// Display coordinates of a world point.
void ToDisplay(vtkRenderer* ren, double x, double y, double z, int& dx, int& dy)
{
  ren->SetWorldPoint(x, y, z, 1.0);
  ren->WorldToDisplay();
  double* d = ren->GetDisplayPoint();
  dx = static_cast<int>(d[0]);
  dy = static_cast<int>(d[1]);
}
}

int TestSuperquadricGlyphMapperInputs(int, char*[])
{
  SplineVizTestStatus status;
  const auto tensors = Tensors();
  Scene scene;

  //----------------------------------------------------------------------------
  // Containers and layouts: identical pictures.
  scene.Mapper->SetInputData(sqtest::TensorImage(tensors, 4));
  const std::vector<unsigned char> reference = scene.Render();
  SV_CHECK(status, scene.Mapper->GetNumberOfGlyphs() == 12);
  SV_CHECK(status, scene.Mapper->GetGPUBytesPerGlyph() == 36);
  SV_CHECK(status, Covered(reference) > 3000);
  {
    vtkNew<vtkUnstructuredGrid> ug;
    ug->SetPoints(GridPoints(0, 12));
    ug->GetPointData()->SetTensors(Encode(tensors, TM::SYMMETRIC_VTK, 0, 12));
    scene.Mapper->SetInputData(ug);
    SV_CHECK_MSG(status, Differ(scene.Render(), reference) == 0, "unstructured grid differs");

    vtkNew<vtkPolyData> pd;
    pd->SetPoints(GridPoints(0, 12));
    pd->GetPointData()->SetTensors(Encode(tensors, TM::SYMMETRIC_VTK, 0, 12));
    scene.Mapper->SetInputData(pd);
    SV_CHECK_MSG(status, Differ(scene.Render(), reference) == 0, "polydata differs");

    vtkNew<vtkMultiBlockDataSet> mb;
    vtkNew<vtkPolyData> b0;
    b0->SetPoints(GridPoints(0, 5));
    b0->GetPointData()->SetTensors(Encode(tensors, TM::SYMMETRIC_VTK, 0, 5));
    vtkNew<vtkUnstructuredGrid> b1;
    b1->SetPoints(GridPoints(5, 7));
    b1->GetPointData()->SetTensors(Encode(tensors, TM::SYMMETRIC_VTK, 5, 7));
    mb->SetBlock(0, b0);
    mb->SetBlock(1, b1);
    scene.Mapper->SetInputData(mb);
    SV_CHECK_MSG(status, Differ(scene.Render(), reference) == 0, "multiblock differs");
    SV_CHECK(status, scene.Mapper->GetNumberOfGlyphs() == 12);

    for (int layout : { TM::SYMMETRIC_LOWER, TM::SYMMETRIC_UPPER, TM::FULL_9, TM::TEEM_7 })
    {
      vtkNew<vtkPolyData> lp;
      lp->SetPoints(GridPoints(0, 12));
      lp->GetPointData()->AddArray(Encode(tensors, layout, 0, 12));
      scene.Mapper->SetInputData(lp);
      scene.Mapper->SetTensorArray("T");
      scene.Mapper->SetTensorLayout(layout);
      SV_CHECK_MSG(status, Differ(scene.Render(), reference) == 0,
        "layout " << TM::GetLayoutName(layout) << " differs");
    }
    // DIPY data read in VTK order: a different (wrong) picture
    vtkNew<vtkPolyData> lp;
    lp->SetPoints(GridPoints(0, 12));
    lp->GetPointData()->AddArray(Encode(tensors, TM::SYMMETRIC_LOWER, 0, 12));
    scene.Mapper->SetInputData(lp);
    scene.Mapper->SetTensorLayout(TM::SYMMETRIC_VTK);
    SV_CHECK(status, Differ(scene.Render(), reference) > 500);
    scene.Mapper->SetTensorArray(nullptr);
  }

  //----------------------------------------------------------------------------
  // Bad input.
  {
    vtkNew<vtkTest::ErrorObserver> observer;
    scene.Mapper->AddObserver(vtkCommand::ErrorEvent, observer);
    scene.Mapper->AddObserver(vtkCommand::WarningEvent, observer);

    auto image = sqtest::TensorImage(tensors, 4);
    scene.Mapper->SetInputData(image);
    scene.Mapper->SetTensorArray("Nope");
    SV_CHECK(status, Covered(scene.Render()) == 0);
    SV_CHECK(status, observer->CheckErrorMessage("No point tensor array named 'Nope'") == 0);
    scene.Mapper->SetTensorArray(nullptr);

    vtkNew<vtkImageData> noTensors;
    noTensors->SetDimensions(4, 3, 1);
    scene.Mapper->SetInputData(noTensors);
    SV_CHECK(status, Covered(scene.Render()) == 0);
    SV_CHECK(status, observer->CheckErrorMessage("No active point tensors") == 0);

    vtkNew<vtkImageData> vectors;
    vectors->SetDimensions(4, 3, 1);
    vtkNew<vtkDoubleArray> v3;
    v3->SetNumberOfComponents(3);
    v3->SetNumberOfTuples(12);
    v3->Fill(1.0);
    v3->SetName("V");
    vectors->GetPointData()->AddArray(v3);
    scene.Mapper->SetInputData(vectors);
    scene.Mapper->SetTensorArray("V");
    SV_CHECK(status, Covered(scene.Render()) == 0);
    SV_CHECK(status, observer->CheckErrorMessage("has 3 components") == 0);
    scene.Mapper->SetTensorArray(nullptr);

    // NaN, infinite and zero tensors: not drawn, the others are.
    auto bad = sqtest::TensorImage(tensors, 4);
    vtkDataArray* t = bad->GetPointData()->GetTensors();
    t->SetComponent(1, 3, std::numeric_limits<double>::quiet_NaN());
    t->SetComponent(6, 0, std::numeric_limits<double>::infinity());
    for (int c = 0; c < 6; ++c)
    {
      t->SetComponent(4, c, 0.0);
    }
    scene.Mapper->SetInputData(bad);
    const std::vector<unsigned char> partial = scene.Render();
    SV_CHECK(status,
      observer->CheckWarningMessage("2 tensors with NaN or infinite components and 1 zero") == 0);
    SV_CHECK(status, scene.Mapper->GetNumberOfGlyphs() == 9);
    SV_CHECK(status, scene.Mapper->GetNumberOfInvalidTensors() == 2);
    SV_CHECK(status, scene.Mapper->GetNumberOfZeroTensors() == 1);
    // the same as drawing only the 9 good tensors
    std::vector<int> keep = { 0, 2, 3, 5, 7, 8, 9, 10, 11 };
    vtkNew<vtkPolyData> good;
    vtkNew<vtkPoints> goodPoints;
    vtkNew<vtkDoubleArray> goodTensors;
    goodTensors->SetNumberOfComponents(6);
    for (int i : keep)
    {
      goodPoints->InsertNextPoint(i % 4, i / 4, 0.0);
      goodTensors->InsertNextTuple(tensors[i].data());
    }
    good->SetPoints(goodPoints);
    good->GetPointData()->SetTensors(goodTensors);
    scene.Mapper->SetInputData(good);
    SV_CHECK_MSG(status, Differ(scene.Render(), partial) == 0, "bad tensors drew something");

    // all zero
    auto zero =
      sqtest::TensorImage(std::vector<std::array<double, 6>>(12, { 0, 0, 0, 0, 0, 0 }), 4);
    scene.Mapper->SetInputData(zero);
    SV_CHECK(status, Covered(scene.Render()) == 0);
    SV_CHECK(status, observer->CheckWarningMessage("12 zero tensors") == 0);
    scene.Mapper->RemoveObserver(observer);
  }

  //----------------------------------------------------------------------------
  // Parameter changes without re-upload.
  {
    auto image = sqtest::TensorImage(tensors, 4);
    vtkNew<vtkSuperquadricGlyphMapper> fresh;
    scene.Actor->SetMapper(fresh);
    fresh->SetInputData(image);
    fresh->SetScaleFactor(0.42);
    fresh->SetNegativeEigenvaluePolicy(vtkSuperquadricGlyphMapper::ABSOLUTE_VALUES);
    std::vector<unsigned char> last = scene.Render();
    SV_CHECK(status, fresh->GetUploadCount() == 1);
    int changed = 0;
    auto step = [&](const char* what)
    {
      std::vector<unsigned char> now = scene.Render();
      SV_CHECK_MSG(status, fresh->GetUploadCount() == 1, what << " re-uploaded the tensors");
      changed += Differ(now, last) > 0;
      last = now;
    };
    fresh->SetGamma(12.0);
    step("gamma");
    fresh->SetScaleFactor(0.3);
    step("scale factor");
    fresh->SetScaleMode(vtkSuperquadricGlyphMapper::SCALE_NORMALIZED);
    step("scale mode");
    fresh->SetAnisotropyThreshold(0.3);
    step("anisotropy threshold");
    fresh->SetMinimumEigenvalue(0.05);
    step("minimum eigenvalue");
    fresh->SetNegativeEigenvaluePolicy(vtkSuperquadricGlyphMapper::SKIP_NEGATIVE);
    step("sign policy");
    fresh->SetGlyphColorMode(vtkSuperquadricGlyphMapper::COLOR_SOLID);
    step("color mode");
    fresh->SetMinimumRoundness(0.5);
    step("minimum roundness");
    fresh->SetMinimumThickness(0.3);
    step("minimum thickness");
    fresh->SetMaximumIterations(4);
    step("iterations");
    SV_CHECK_MSG(status, changed >= 9, "only " << changed << " parameter changes showed");
    // new data: uploaded once
    image->GetPointData()->GetTensors()->SetComponent(0, 0, 2.0);
    image->GetPointData()->GetTensors()->Modified();
    scene.Render();
    scene.Render();
    SV_CHECK(status, fresh->GetUploadCount() == 2);
    scene.Actor->SetMapper(scene.Mapper);
  }

  //----------------------------------------------------------------------------
  // Thresholds, mask, scale modes.
  {
    auto image = sqtest::TensorImage(tensors, 4);
    scene.Mapper->SetInputData(image);
    const int all = Covered(scene.Render());
    scene.Mapper->SetAnisotropyThreshold(0.999);
    SV_CHECK(status, Covered(scene.Render()) == 0);
    scene.Mapper->SetAnisotropyThreshold(0.0);
    scene.Mapper->SetMinimumEigenvalue(0.5); // only "nearly spherical" (l3 = 0.9)
    const int one = Covered(scene.Render());
    SV_CHECK_MSG(status, one > 100 && one < all / 4, "minimum eigenvalue: " << one);
    scene.Mapper->SetMinimumEigenvalue(-VTK_DOUBLE_MAX);

    vtkNew<vtkIntArray> mask;
    mask->SetName("Mask");
    for (int i = 0; i < 12; ++i)
    {
      mask->InsertNextValue(i % 2);
    }
    image->GetPointData()->AddArray(mask);
    scene.Mapper->SetMaskArray("Mask");
    const int half = Covered(scene.Render());
    SV_CHECK(status, scene.Mapper->GetNumberOfGlyphs() == 6);
    SV_CHECK(status, scene.Mapper->GetNumberOfMaskedPoints() == 6);
    SV_CHECK(status, half > 0 && half < all);

    // Picking through the mask: glyph 7 ("axis aligned", not masked).
    int dx, dy;
    ToDisplay(scene.Renderer, 3.0, 1.0, 0.0, dx, dy);
    std::set<vtkIdType> picked = PickPoints(scene, dx - 2, dy - 2, dx + 2, dy + 2);
    SV_CHECK_MSG(status, picked.size() == 1 && *picked.begin() == 7,
      "picked " << picked.size() << " points, first " << (picked.empty() ? -1 : *picked.begin()));
    ToDisplay(scene.Renderer, 1.0, 2.0, 0.0, dx, dy);
    picked = PickPoints(scene, dx - 2, dy - 2, dx + 2, dy + 2);
    SV_CHECK_MSG(status, picked.size() == 1 && *picked.begin() == 9, "picked point 9");
    // a masked point's place is empty
    ToDisplay(scene.Renderer, 2.0, 1.0, 0.0, dx, dy);
    picked = PickPoints(scene, dx - 1, dy - 1, dx + 1, dy + 1);
    SV_CHECK(status, picked.empty() || picked.count(6) == 0);
    scene.Mapper->SetMaskArray(nullptr);

    // Normalized sizes do not depend on the tensors' magnitude.
    std::vector<std::array<double, 6>> big = tensors;
    for (auto& t : big)
    {
      for (double& c : t)
      {
        c *= 10.0;
      }
    }
    scene.Mapper->SetScaleMode(vtkSuperquadricGlyphMapper::SCALE_NORMALIZED);
    scene.Mapper->SetInputData(sqtest::TensorImage(tensors, 4));
    const std::vector<unsigned char> normalized = scene.Render();
    scene.Mapper->SetInputData(sqtest::TensorImage(big, 4));
    {
      // same shapes; float rounding may change the shading by a unit
      const int d = Differ(scene.Render(), normalized, 3);
      SV_CHECK_MSG(status, d <= 3, "normalized 10x differs " << d);
    }
    // Clamped: every 10x glyph is larger than 0.42, so clamping at 0.42
    // gives the normalized picture.
    scene.Mapper->SetScaleMode(vtkSuperquadricGlyphMapper::SCALE_CLAMPED);
    scene.Mapper->SetMaximumScale(0.42);
    SV_CHECK(status, Differ(scene.Render(), normalized, 3) <= 3);
    scene.Mapper->SetMaximumScale(100.0); // not clamped: 10x larger
    SV_CHECK(status, Covered(scene.Render()) > Covered(normalized) * 3 / 2);
    scene.Mapper->SetScaleMode(vtkSuperquadricGlyphMapper::SCALE_BY_EIGENVALUES);
  }

  //----------------------------------------------------------------------------
  // The camera inside a glyph's box: the sprite crosses the near plane.
  {
    scene.Mapper->SetInputData(sqtest::TensorImage(tensors, 4));
    vtkCamera* camera = scene.Renderer->GetActiveCamera();
    camera->SetPosition(0.05, 0.0, 0.3);
    camera->SetFocalPoint(2.0, 1.0, 0.0);
    camera->SetClippingRange(0.01, 10.0);
    SV_CHECK(status, Covered(scene.Render()) > 0);
  }

  return status.Result();
}
