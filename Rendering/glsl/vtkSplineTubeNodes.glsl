// SPDX-License-Identifier: BSD-3-Clause
// The tubes buffer of the spline-tube mappers (vtkSplineTubeMapper), read by
// every stage that needs a tube's nodes. Needs the spline-tube math
// (vtkSplineTubeMathShared.glsl) before it.
//
// Per node one RGBA32F texel of `tubeNodes` (position relative to the
// mapper's shift, radius), or an RGB32F texel (the position alone) when every
// node has the radius tubeConstantRadius (not negative; see
// vtkSplineTubeMapper::UploadNodes()), and one R32UI texel of `tubeNodeInfo` (the node's
// tube, | 1 << 30 for the first node of the tube, | 1 << 31 for its last).
// The derivatives along the tube are not stored: svNodeDerivative() makes
// them from the neighbours, as vtkSplineTubeCore does on the CPU.
uniform samplerBuffer tubeNodes;
uniform usamplerBuffer tubeNodeInfo;
uniform float tubeConstantRadius; // < 0: each node's radius is in tubeNodes

const uint tubeFirstNodeBit = 0x40000000u;
const uint tubeLastNodeBit = 0x80000000u;

// The tube of a node.
int tubeOfNode(int node)
{
  return int(texelFetch(tubeNodeInfo, node).x & 0x3FFFFFFFu);
}

// Position and radius of a node (shifted model coordinates).
vec4 tubeNodeModel(int node)
{
  vec4 n = texelFetch(tubeNodes, node);
  return tubeConstantRadius < 0.0 ? n : vec4(n.xyz, tubeConstantRadius);
}

// Where a node's tube ends around it, for svNodeDerivative(): the indices of
// the nodes two and one before and after it (clamped to the tube), and
// whether it, the one before or the one after is the tube's first or last.
struct TubeNeighbours
{
  ivec4 nodes; // prev2, prev, next, next2
  bool first;
  bool last;
  bool prevIsFirst;
  bool nextIsLast;
};

TubeNeighbours tubeNeighbours(int node)
{
  TubeNeighbours n;
  uint info = texelFetch(tubeNodeInfo, node).x;
  n.first = (info & tubeFirstNodeBit) != 0u;
  n.last = (info & tubeLastNodeBit) != 0u;
  n.prevIsFirst = !n.first && (texelFetch(tubeNodeInfo, node - 1).x & tubeFirstNodeBit) != 0u;
  n.nextIsLast = !n.last && (texelFetch(tubeNodeInfo, node + 1).x & tubeLastNodeBit) != 0u;
  int prev = n.first ? node : node - 1;
  int next = n.last ? node : node + 1;
  n.nodes = ivec4(n.first || n.prevIsFirst ? prev : node - 2, prev, next,
    n.last || n.nextIsLast ? next : node + 2);
  return n;
}

// The derivative of the position and radius splines at a node (shifted
// model coordinates, per unit of the node parameter).
vec4 tubeNodeDerivativeModel(int node)
{
  TubeNeighbours n = tubeNeighbours(node);
  return svNodeDerivative(tubeNodeModel(n.nodes.x), tubeNodeModel(n.nodes.y),
    tubeNodeModel(node), tubeNodeModel(n.nodes.z), tubeNodeModel(n.nodes.w), n.first, n.last,
    n.prevIsFirst, n.nextIsLast);
}

// The segment from `node` to the next: its ends and their derivatives
// (shifted model coordinates), its flags (1: it starts its tube, 2: it ends
// it) and its tube.
void tubeSegmentModel(int node, out vec4 p0, out vec4 m0, out vec4 p1, out vec4 m1,
  out int flags, out int tube)
{
  uint a = texelFetch(tubeNodeInfo, node).x;
  uint b = texelFetch(tubeNodeInfo, node + 1).x;
  p0 = tubeNodeModel(node);
  p1 = tubeNodeModel(node + 1);
  m0 = tubeNodeDerivativeModel(node);
  m1 = tubeNodeDerivativeModel(node + 1);
  flags = ((a & tubeFirstNodeBit) != 0u ? 1 : 0) | ((b & tubeLastNodeBit) != 0u ? 2 : 0);
  tube = int(a & 0x3FFFFFFFu);
}
