// SPDX-License-Identifier: BSD-3-Clause
//VTK::System::Dec
//SV::LineAmbientOcclusionCommon::Dec
// Tiles for the halo stage of vtkLineAmbientOcclusionPass: the window is cut
// into aoTileSize x aoTileSize pixel tiles, drawn as two triangles each
// (glDrawArrays(GL_TRIANGLES, 0, 6 x tiles), no vertex attributes), and a
// tile that cannot hold a halo pixel collapses to a point, so that no
// fragment of it is shaded (on a CPU rasterizer such as llvmpipe, where an
// if in a shader saves nothing, this is what skips the work).
//
// A pixel P is in a halo only if some pixel Q within the halo's reach lies
// more than the halo's depth offset in front of P. aoTiles holds for each
// tile the view z of its nearest pixel (x; -1e30 when the tile is all
// background) and of its farthest (y; -1e30 when it holds background, which
// is infinitely far). The tile is drawn when the nearest pixel of the tiles
// within aoTileReach tiles lies more than the offset in front of its own
// farthest (aoHaloGap). Conservative: every drawn pixel is shaded exactly as
// a full-screen pass would shade it, and a skipped pixel's halo is zero.
//
// Outputs the full-screen template's texCoord, so that the halo stage's
// fragment code is the same as in a full-screen pass, and the nearest view z
// within reach, with which a pixel that nothing lies in front of skips its
// samples.

uniform sampler2D aoTiles;
uniform ivec2 aoTileCount; // tiles along x and y
uniform int aoTileSize;    // pixels per tile side
uniform int aoTileReach;   // tiles on each side within the halo's reach
uniform ivec2 aoSize;      // the window's size in pixels

out vec2 texCoord;
flat out float aoTileNearest; // the nearest view z within reach, for the halo stage

void main()
{
  int tile = gl_VertexID / 6;
  int corner = gl_VertexID - 6 * tile;
  ivec2 t = ivec2(tile % aoTileCount.x, tile / aoTileCount.x);
  float farthest = texelFetch(aoTiles, t, 0).y;
  float nearest = -1.0e30;
  for (int dy = -aoTileReach; dy <= aoTileReach; ++dy)
  {
    for (int dx = -aoTileReach; dx <= aoTileReach; ++dx)
    {
      ivec2 n = clamp(t + ivec2(dx, dy), ivec2(0), aoTileCount - 1);
      nearest = max(nearest, texelFetch(aoTiles, n, 0).x);
    }
  }
  // Two triangles: corners (0,0) (1,0) (1,1) and (0,0) (1,1) (0,1).
  ivec2 c = ivec2(corner == 1 || corner == 2 || corner == 4 ? 1 : 0,
    corner == 2 || corner == 4 || corner == 5 ? 1 : 0);
  if (!(nearest > -1.0e29 && aoHaloGap(nearest, farthest) > aoHaloOffset))
  {
    c = ivec2(0); // collapsed: nothing to rasterize
  }
  aoTileNearest = nearest;
  vec2 pixel = vec2(min((t + c) * aoTileSize, aoSize));
  texCoord = pixel / vec2(aoSize);
  gl_Position = vec4(2.0 * texCoord - 1.0, 0.0, 1.0);
}
