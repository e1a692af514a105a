// SPDX-License-Identifier: BSD-3-Clause
// Scalar coloring of spline tubes (vtkSplineTubeMapper), shared by every
// stage that evaluates the color spline. Needs the spline-tube math
// (vtkSplineTubeMathShared.glsl) and the tubes buffer
// (vtkSplineTubeNodes.glsl) before it.
//
// Per node one R32UI texel of `tubeColors`: the mapped color (RGBA8). The
// color spline is a cubic Hermite spline through the nodes' colors with the
// derivatives of the position spline's rule (svNodeDerivative()).
uniform usamplerBuffer tubeColors;

// A node's color, components in [0, 1].
vec4 tubeNodeColor(int node)
{
  uint v = texelFetch(tubeColors, node).x;
  return vec4(uvec4(v, v >> 8u, v >> 16u, v >> 24u) & uvec4(0xFFu)) / 255.0;
}

// The derivative of the color spline at a node.
vec4 tubeNodeColorDerivative(int node)
{
  TubeNeighbours n = tubeNeighbours(node);
  return svNodeDerivative(tubeNodeColor(n.nodes.x), tubeNodeColor(n.nodes.y), tubeNodeColor(node),
    tubeNodeColor(n.nodes.z), tubeNodeColor(n.nodes.w), n.first, n.last, n.prevIsFirst,
    n.nextIsLast);
}

// The color spline of the segment from `node` at curve parameter t.
vec4 tubeColorSpline(int node, float t)
{
  return clamp(svHermite(tubeNodeColor(node), tubeNodeColorDerivative(node),
                 tubeNodeColor(node + 1), tubeNodeColorDerivative(node + 1), t),
    0.0, 1.0);
}
