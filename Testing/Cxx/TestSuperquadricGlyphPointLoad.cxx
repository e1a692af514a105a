// SPDX-License-Identifier: BSD-3-Clause
// Image regression test of vtkSuperquadricGlyphMapper on an indefinite
// tensor field: the Boussinesq stress tensors of vtkPointLoad (9 components,
// mixed-sign eigenvalues), left with the default policy (tensors with a
// negative eigenvalue are skipped: only the few positive semi-definite ones
// remain), right with absolute values; sizes normalized, colored by the
// effective stress through a lookup table.
#include "vtkSuperquadricGlyphMapper.h"
#include "PointLoadGlyphScene.h"

#include <iostream>

int TestSuperquadricGlyphPointLoad(int argc, char* argv[])
{
  sqtest::PointLoadScene scene;
  vtkRenderWindow* window = scene.Window;
  vtkLookupTable* lut = scene.Lut;
  const double* range = scene.Range;

  for (int v = 0; v < 2; ++v)
  {
    vtkNew<vtkSuperquadricGlyphMapper> mapper;
    mapper->SetInputConnection(scene.Load->GetOutputPort());
    mapper->SetNegativeEigenvaluePolicy(v == 0 ? vtkSuperquadricGlyphMapper::SKIP_NEGATIVE
                                               : vtkSuperquadricGlyphMapper::ABSOLUTE_VALUES);
    mapper->SetScaleMode(vtkSuperquadricGlyphMapper::SCALE_NORMALIZED);
    mapper->SetScaleFactor(1.4);
    mapper->SetGamma(3.0);
    mapper->SetGlyphColorMode(vtkSuperquadricGlyphMapper::COLOR_BY_SCALARS);
    mapper->SetScalarRange(range[0], range[1]);
    mapper->SetLookupTable(lut);
    sqtest::AddPointLoadView(window, scene.Load, mapper, v);
    window->Render();
    std::cout << (v == 0 ? "skip" : "absolute") << ": " << mapper->GetNumberOfGlyphs()
              << " glyphs uploaded" << std::endl;
  }

  return sqtest::ComparePointLoadImage(argc, argv, window) ? 0 : 1;
}
