// SPDX-License-Identifier: BSD-3-Clause
// vtkTensorLineTracer on a real diffusion data set: DIPY's small_64D DWI
// volume with tensors fitted by DIPY (Testing/Data/DIPY/small_64D_dti.vti,
// see its PROVENANCE.md; DIPY's lower-triangular layout), seeded at every
// voxel with FA >= 0.3. Checked against independent code:
//  - the seeds are exactly the voxels where DIPY's own FA reaches 0.3, and
//    at each seed our FA and principal direction equal DIPY's;
//  - at every output point the "Tensors" output equals VTK's vtkProbeFilter
//    (trilinear) interpolation of the stored DTI array, converted from
//    DIPY's order here, and FractionalAnisotropy / PrincipalDirection equal
//    FA and e1 of that tensor from vtkMath::Jacobi;
//  - the stopping contract holds on real data (FA, turning angle, domain),
//    the two fit failures (zero tensors) do not disturb it, and the lines
//    follow their principal directions (each step's chord agrees in sign
//    with the mean direction at its ends, within 5 degrees for 99 %, and
//    is at least half the step long).
#include "vtkTensorLineTracer.h"

#include "SplineVizTestUtilities.h"
#include "TensorLineTestFields.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProbeFilter.h"
#include "vtkXMLImageDataReader.h"

#include <cmath>
#include <iostream>
#include <map>
#include <string>

using namespace TensorLineTest;

int TestTensorLineTracerDIPY(int, char*[])
{
  SplineVizTestStatus status;
  vtkNew<vtkXMLImageDataReader> reader;
  reader->SetFileName((std::string(SPLINEVIZ_SOURCE_DATA_DIR) + "/DIPY/small_64D_dti.vti").c_str());
  reader->Update();
  vtkImageData* img = reader->GetOutput();
  vtkDataArray* dti = img->GetPointData()->GetArray("DTI");
  vtkDataArray* faDipy = img->GetPointData()->GetArray("FA_DIPY");
  vtkDataArray* e1Dipy = img->GetPointData()->GetArray("Evec1_DIPY");
  SV_CHECK(status, dti && faDipy && e1Dipy && img->GetNumberOfPoints() == 1000);
  if (!dti || !faDipy || !e1Dipy)
  {
    return EXIT_FAILURE;
  }

  const double seedFA = 0.3, stopFA = 0.15, maxAngle = 45.0;
  vtkNew<vtkTensorLineTracer> tracer;
  tracer->SetInputConnection(reader->GetOutputPort());
  tracer->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "DTI");
  tracer->SetTensorLayout(2); // DIPY: XX XY YY XZ YZ ZZ
  tracer->SetSeedMode(vtkTensorLineTracer::SEEDS_FROM_VOXELS);
  tracer->SetSeedFAThreshold(seedFA);
  tracer->SetStoppingFAThreshold(stopFA);
  tracer->SetMaximumAngle(maxAngle);
  tracer->SetIntegrationStep(0.25); // 0.5 mm
  tracer->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  tracer->Update();
  vtkPolyData* out = tracer->GetOutput();
  const auto lines = GetLines(out);

  // Seeds: the voxels where DIPY's FA >= 0.3 (ties within float rounding
  // of the threshold are counted as uncertain).
  vtkIdType expected = 0, uncertain = 0;
  for (vtkIdType i = 0; i < img->GetNumberOfPoints(); ++i)
  {
    const double fa = faDipy->GetComponent(i, 0);
    expected += fa >= seedFA ? 1 : 0;
    uncertain += std::abs(fa - seedFA) < 1e-5 ? 1 : 0;
  }
  std::cout << "DIPY small_64D: " << tracer->GetNumberOfSeeds() << " seeds (DIPY: " << expected
            << " voxels with FA >= " << seedFA << "), " << out->GetNumberOfLines() << " lines, "
            << out->GetNumberOfPoints() << " points, " << tracer->GetNumberOfShortLines()
            << " single-point lines" << std::endl;
  SV_CHECK(status, std::abs(tracer->GetNumberOfSeeds() - expected) <= uncertain);
  SV_CHECK(status,
    out->GetNumberOfLines() + tracer->GetNumberOfShortLines() == tracer->GetNumberOfSeeds());
  SV_CHECK(status, out->GetNumberOfLines() > 400);

  // At the seeds: DIPY's FA and principal eigenvector.
  double worstSeedFA = 0.0, worstSeedDir = 0.0;
  for (const TracedLine& l : lines)
  {
    for (std::size_t i = 0; i < l.Points.size(); ++i)
    {
      if (l.Arc[i] != 0.0)
      {
        continue;
      }
      Vec3 x = l.Points[i];
      const vtkIdType id = img->FindPoint(x.data());
      double p[3];
      img->GetPoint(id, p);
      SV_CHECK(status,
        Norm({ p[0] - l.Points[i][0], p[1] - l.Points[i][1], p[2] - l.Points[i][2] }) == 0.0);
      worstSeedFA = std::max(worstSeedFA, std::abs(l.FA[i] - faDipy->GetComponent(id, 0)));
      Vec3 e;
      e1Dipy->GetTuple(id, e.data());
      worstSeedDir = std::max(worstSeedDir, 1.0 - std::abs(Dot(e, l.Directions[i])));
    }
  }
  std::cout << "at the seeds vs DIPY: largest FA difference " << worstSeedFA
            << ", largest 1 - |cos| of the principal directions " << worstSeedDir << std::endl;
  SV_CHECK(status, worstSeedFA < 1e-5);
  SV_CHECK(status, worstSeedDir < 1e-6);

  // Everywhere: the interpolated tensor against vtkProbeFilter, FA and e1 of it
  // against vtkMath::Jacobi.
  vtkNew<vtkProbeFilter> probe;
  probe->SetInputData(out);
  probe->SetSourceConnection(reader->GetOutputPort());
  probe->Update();
  vtkDataArray* probed =
    vtkDataSet::SafeDownCast(probe->GetOutput())->GetPointData()->GetArray("DTI");
  vtkDataArray* tensors = out->GetPointData()->GetArray("Tensors");
  vtkDataArray* fa = out->GetPointData()->GetArray("FractionalAnisotropy");
  vtkDataArray* dir = out->GetPointData()->GetArray("PrincipalDirection");
  double worstT = 0.0, worstFA = 0.0, worstDir = 0.0, scale = 0.0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double c[6], t[6];
    probed->GetTuple(i, c);
    // DIPY's XX XY YY XZ YZ ZZ -> XX YY ZZ XY YZ XZ
    const double mine[6] = { c[0], c[2], c[5], c[1], c[4], c[3] };
    tensors->GetTuple(i, t);
    double m[3][3] = { { mine[0], mine[3], mine[5] }, { mine[3], mine[1], mine[4] },
      { mine[5], mine[4], mine[2] } };
    for (int k = 0; k < 6; ++k)
    {
      worstT = std::max(worstT, std::abs(t[k] - mine[k]));
      scale = std::max(scale, std::abs(mine[k]));
    }
    double w[3], v[3][3];
    double* mp[3] = { m[0], m[1], m[2] };
    double* vp[3] = { v[0], v[1], v[2] };
    vtkMath::Jacobi(mp, w, vp);
    const double mean = (w[0] + w[1] + w[2]) / 3.0;
    const double faJ = std::sqrt(1.5 *
      ((w[0] - mean) * (w[0] - mean) + (w[1] - mean) * (w[1] - mean) +
        (w[2] - mean) * (w[2] - mean)) /
      (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]));
    worstFA = std::max(worstFA, std::abs(faJ - fa->GetComponent(i, 0)));
    const Vec3 e = { v[0][0], v[1][0], v[2][0] }; // Jacobi: eigenvectors in columns
    Vec3 d;
    dir->GetTuple(i, d.data());
    if (w[0] - w[1] > 1e-3 * w[0]) // a well-defined principal direction
    {
      worstDir = std::max(worstDir, 1.0 - std::abs(Dot(e, d)));
    }
  }
  std::cout << "along the lines: tensor vs vtkProbeFilter " << worstT / scale
            << " (relative), FA vs Jacobi " << worstFA << ", 1 - |cos| of e1 vs Jacobi " << worstDir
            << std::endl;
  SV_CHECK(status, worstT < 1e-6 * scale);
  SV_CHECK(status, worstFA < 1e-6);
  SV_CHECK(status, worstDir < 1e-6);

  // The stopping contract and the lines following their directions.
  double bounds[6];
  img->GetBounds(bounds);
  bool inside = true, faOk = true, anglesOk = true, follows = true;
  vtkIdType steps = 0, aligned = 0;
  std::map<int, int> reasons;
  for (const TracedLine& l : lines)
  {
    reasons[l.Reasons[0]]++;
    reasons[l.Reasons[1]]++;
    for (std::size_t i = 0; i < l.Points.size(); ++i)
    {
      for (int a = 0; a < 3; ++a)
      {
        inside = inside && l.Points[i][a] >= bounds[2 * a] - 1e-9 &&
          l.Points[i][a] <= bounds[2 * a + 1] + 1e-9;
      }
      faOk = faOk && l.FA[i] >= stopFA;
      if (i > 0)
      {
        const Vec3 chord = Normalized({ l.Points[i][0] - l.Points[i - 1][0],
          l.Points[i][1] - l.Points[i - 1][1], l.Points[i][2] - l.Points[i - 1][2] });
        // the chord of an RK4 step is a weighted mean of the directions
        // along the step: close to the mean of the directions at its ends
        const Vec3 mean = { l.Directions[i][0] + l.Directions[i - 1][0],
          l.Directions[i][1] + l.Directions[i - 1][1],
          l.Directions[i][2] + l.Directions[i - 1][2] };
        const double c = Dot(chord, Normalized(mean));
        follows = follows && c > 0.0;
        // every step advances at least half the step (no crawling across
        // the principal direction when the field turns sharply)
        const double len = Norm({ l.Points[i][0] - l.Points[i - 1][0],
          l.Points[i][1] - l.Points[i - 1][1], l.Points[i][2] - l.Points[i - 1][2] });
        follows = follows && len >= 0.5 * tracer->GetStepLength();
        ++steps;
        aligned += c > std::cos(vtkMath::RadiansFromDegrees(5.0)) ? 1 : 0;
        if (i + 1 < l.Points.size() && l.Arc[i] != 0.0)
        {
          const Vec3 next = Normalized({ l.Points[i + 1][0] - l.Points[i][0],
            l.Points[i + 1][1] - l.Points[i][1], l.Points[i + 1][2] - l.Points[i][2] });
          anglesOk =
            anglesOk && Dot(chord, next) >= std::cos(vtkMath::RadiansFromDegrees(maxAngle)) - 1e-12;
        }
      }
    }
  }
  std::cout << "reasons:";
  for (const auto& r : reasons)
  {
    std::cout << " " << vtkTensorLineTracer::GetReasonName(r.first) << " " << r.second << ";";
  }
  std::cout << std::endl;
  SV_CHECK(status, inside);
  SV_CHECK(status, faOk);
  SV_CHECK(status, anglesOk);
  SV_CHECK(status, follows);
  std::cout << "steps within 5 degrees of the mean direction at their ends: " << aligned << " of "
            << steps << std::endl;
  SV_CHECK(status, aligned > 0.99 * steps);
  SV_CHECK(status, reasons[vtkTensorLineTracer::LOW_ANISOTROPY] > 0);
  SV_CHECK(status, reasons[vtkTensorLineTracer::HIGH_CURVATURE] > 0);
  SV_CHECK(status, reasons[vtkTensorLineTracer::OUT_OF_DOMAIN] > 0);
  return status.Result();
}
