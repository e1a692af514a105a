// SPDX-License-Identifier: BSD-3-Clause
//VTK::System::Dec
//SV::LineAmbientOcclusionCommon::Dec
// Tiles for the halo stage of vtkLineAmbientOcclusionPass: the window is cut
// into tiles of 2 x 2 blocks (aoBlockSize pixels a side), drawn as two
// triangles each (glDrawArrays(GL_TRIANGLES, 0, 6 x tiles), no vertex
// attributes), and a tile that cannot hold a halo pixel collapses to a
// point, so that no fragment of it is shaded (on a CPU rasterizer such as
// llvmpipe, where an if in a shader saves nothing, this is what skips the
// work).
//
// A pixel P is in a halo only if some pixel Q within the halo's reach lies
// far enough in front of P. aoBlockReach holds for each block the view z of
// the nearest pixel within reach of any of its pixels (x; -1e30 when there
// is none) and of the block's farthest (y; -1e30 when it holds background,
// which is infinitely far). The tile is drawn when it holds background and
// some geometry lies within reach, or when the nearest pixel within reach is
// far enough in front of its farthest to give the innermost samples a halo
// (aoHaloGap, aoHaloWeight). Conservative: every drawn pixel is shaded
// exactly as a full-screen pass would shade it, and a skipped pixel's halo
// is zero.
//
// Outputs the full-screen template's texCoord, so that the halo stage's
// fragment code is the same as in a full-screen pass.

uniform sampler2D aoBlockReach;
uniform ivec2 aoBlockCount; // blocks along x and y
uniform int aoBlockSize;    // pixels per block side
uniform ivec2 aoTileCount;  // tiles (2 x 2 blocks) along x and y
uniform ivec2 aoSize;       // the window's size in pixels

out vec2 texCoord;

void main()
{
  int tile = gl_VertexID / 6;
  int corner = gl_VertexID - 6 * tile;
  ivec2 t = ivec2(tile % aoTileCount.x, tile / aoTileCount.x);
  float nearest = -1.0e30;
  float farthest = 1.0e30;
  for (int dy = 0; dy <= 1; ++dy)
  {
    for (int dx = 0; dx <= 1; ++dx)
    {
      vec2 b = texelFetch(aoBlockReach, min(2 * t + ivec2(dx, dy), aoBlockCount - 1), 0).xy;
      nearest = max(nearest, b.x);
      farthest = min(farthest, b.y);
    }
  }
  bool drawn = farthest < -1.0e29
    ? nearest > -1.0e29
    : aoHaloGap(nearest, farthest) > aoHaloOffset &&
      aoHaloRingCoverage(aoHaloWeight(aoHaloGap(nearest, farthest)), aoHaloWidth / 3.0) > 0.0;
  // Two triangles: corners (0,0) (1,0) (1,1) and (0,0) (1,1) (0,1).
  ivec2 c = ivec2(corner == 1 || corner == 2 || corner == 4 ? 1 : 0,
    corner == 2 || corner == 4 || corner == 5 ? 1 : 0);
#ifdef LINE_AO_FULL_SEARCH
  drawn = true; // (for tests) every tile
#endif
  if (!drawn)
  {
    c = ivec2(0); // collapsed: nothing to rasterize
  }
  vec2 pixel = vec2(min((t + c) * 2 * aoBlockSize, aoSize));
  texCoord = pixel / vec2(aoSize);
  gl_Position = vec4(2.0 * texCoord - 1.0, 0.0, 1.0);
}
