// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLRSplineParser
 * @brief   Parses LRSplines text patches (.lr, volumes and surfaces, several patches) and GoTools
 * g2 spline patches (classes 200, 700, 293, 793) into vtkLRSplinePatch.
 *
 * Plain C++ (not a vtkObject), used by vtkLRSplineReader and vtkIFEMReader.
 * The formats are described in docs/spline-formats.md: LRSplines'
 * "# LRSPLINE VOLUME" / "# LRSPLINE SURFACE" text; GoTools' tensor-product
 * SplineSurface (200) and SplineVolume (700), rational ones with homogeneous
 * coefficients; GoTools' own LRSplineSurface (293) and LRSplineVolume (793),
 * whose elements are rebuilt from the mesh rectangles stored over the
 * distinct knots. Surfaces become patches of ParametricDimension 2 and
 * rational g2 patches set RationalCoefficients (see vtkLRSplinePatch).
 *
 * The parser is strict and never trusts a count: it reads token by token,
 * tracks line numbers, and every error message starts with "line N: " (N the
 * line of the offending token; the last line for a truncated file). Knot
 * vectors must have exactly order + 1 values; counts in headers must match
 * what follows; unknown headers, curves and pre-2013 LR surfaces are rejected
 * with a message that says what was found. Values are checked by
 * vtkLRSplinePatch::Validate() (called by Parse), so NaN or infinite numbers
 * are reported with their line too.
 */

#ifndef vtkLRSplineParser_h
#define vtkLRSplineParser_h

#include "SplineVizIOModule.h" // for export macro
#include "vtkLRSplinePatch.h"

#include <string>
#include <vector>

class SPLINEVIZIO_EXPORT vtkLRSplineParser
{
public:
  enum Format
  {
    AUTOMATIC = 0, ///< from the content: '#' first means LRSplines, a number means g2
    LRSPLINES = 1,
    G2 = 2
  };

  /// Parse a whole file's text. False with a message (naming the line) on error.
  static bool Parse(const std::string& text, int format, std::vector<vtkLRSplinePatch>& patches,
    std::string* error);

  /// The format of a text (LRSPLINES or G2), AUTOMATIC when it cannot tell.
  static int DetectFormat(const std::string& text);

  static bool ParseLRSplines(
    const std::string& text, std::vector<vtkLRSplinePatch>& patches, std::string* error);
  static bool ParseG2(
    const std::string& text, std::vector<vtkLRSplinePatch>& patches, std::string* error);
};

#endif
// VTK-HeaderTest-Exclude: vtkLRSplineParser.h
