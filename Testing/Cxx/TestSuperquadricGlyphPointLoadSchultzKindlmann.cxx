// SPDX-License-Identifier: BSD-3-Clause
// Image regression test of the Schultz-Kindlmann glyphs
// (NegativeEigenvaluePolicy SCHULTZ_KINDLMANN) on the indefinite stress field
// of vtkPointLoad (the Boussinesq solution, 9 components, mixed-sign
// eigenvalues), the field TestSuperquadricGlyphPointLoad draws with the
// skip and absolute-value policies: left colored by the sign of the
// quadratic form x^T T x (orange tension, blue compression), right by the
// effective stress through a lookup table; sizes normalized. Also checks
// that every finite non-zero tensor gets a glyph (the skip policy keeps only
// the few definite ones). The shapes themselves are checked against an
// independent reference in TestSuperquadricGlyphSchultzKindlmann.
#include "vtkSuperquadricGlyphMapper.h"
#include "PointLoadGlyphScene.h"

#include <iostream>

int TestSuperquadricGlyphPointLoadSchultzKindlmann(int argc, char* argv[])
{
  sqtest::PointLoadScene scene;
  vtkImageData* stress = scene.Stress;
  vtkRenderWindow* window = scene.Window;
  vtkLookupTable* lut = scene.Lut;
  const double* range = scene.Range;
  int failures = 0;

  for (int v = 0; v < 2; ++v)
  {
    vtkNew<vtkSuperquadricGlyphMapper> mapper;
    mapper->SetInputConnection(scene.Load->GetOutputPort());
    mapper->SetNegativeEigenvaluePolicyToSchultzKindlmann();
    mapper->SetScaleMode(vtkSuperquadricGlyphMapper::SCALE_NORMALIZED);
    mapper->SetScaleFactor(1.4);
    mapper->SetGamma(3.0);
    if (v == 0)
    {
      mapper->SetGlyphColorModeToQuadraticForm();
    }
    else
    {
      mapper->SetGlyphColorModeToScalars();
      mapper->SetScalarRange(range[0], range[1]);
      mapper->SetLookupTable(lut);
    }
    sqtest::AddPointLoadView(window, scene.Load, mapper, v);
    window->Render();
    const vtkIdType drawn = mapper->GetNumberOfGlyphs();
    const vtkIdType left = mapper->GetNumberOfInvalidTensors() + mapper->GetNumberOfZeroTensors();
    std::cout << (v == 0 ? "quadratic form" : "effective stress") << ": " << drawn << " glyphs, "
              << left << " invalid or zero tensors of " << stress->GetNumberOfPoints() << " points"
              << std::endl;
    if (drawn + left != stress->GetNumberOfPoints() || drawn < stress->GetNumberOfPoints() - 7)
    {
      std::cerr << "Schultz-Kindlmann: not every finite non-zero tensor got a glyph" << std::endl;
      ++failures;
    }
  }

  const bool imageOk = sqtest::ComparePointLoadImage(argc, argv, window);
  return (!imageOk || failures) ? 1 : 0;
}
