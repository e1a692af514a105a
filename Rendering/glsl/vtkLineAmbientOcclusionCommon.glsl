// SPDX-License-Identifier: BSD-3-Clause
// What the fragment stages of vtkLineAmbientOcclusionPass
// (vtkLineAmbientOcclusionFS.glsl) and its halo tiles
// (vtkLineAmbientOcclusionTilesVS.glsl) both compute: sizes and depth gaps
// in the pass's length units. The pass puts it before both.

uniform vec2 aoClipW;       // clip w = aoClipW.x * z_view + aoClipW.y
uniform float aoPixelScale; // one pixel in view units = aoPixelScale x clip w
uniform int aoWorldUnits;   // radius and depth gaps: 1 view units, 0 pixels
uniform float aoHaloWidth;  // pixels
uniform float aoHaloOffset; // the depth gap below which there is no halo
uniform float aoHaloRange;  // the depth gap beyond the offset to the full width

// The size of one pixel in view units at view depth z.
float aoPixelSize(float z)
{
  return aoPixelScale * (aoClipW.x * z + aoClipW.y);
}

// How far a point at view z `behind` lies behind one at view z `front`, in
// the pass's length units (pixels: at the front point's distance). For a
// fixed `behind` it grows with `front` (nearer: larger), so the nearest
// point around a pixel bounds the gap of every other.
float aoHaloGap(float front, float behind)
{
  float gap = front - behind;
  return aoWorldUnits != 0 ? gap : gap / aoPixelSize(front);
}

// The share of the halo's width a point `gap` in front gives (the gap in
// the pass's length units).
float aoHaloWeight(float gap)
{
  return aoHaloRange > 0.0 ? clamp((gap - aoHaloOffset) / aoHaloRange, 0.0, 1.0)
                           : (gap > aoHaloOffset ? 1.0 : 0.0);
}

// The halo coverage a sample s pixels away with weight w gives; it grows
// with w.
float aoHaloRingCoverage(float w, float s)
{
  return clamp(aoHaloWidth * w - s + 0.5, 0.0, 1.0);
}
