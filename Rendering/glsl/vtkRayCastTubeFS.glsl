// SPDX-License-Identifier: BSD-3-Clause
// Ray-cast spline tubes (Salm §3.2), fragment-stage declarations.
//
// Inserted into VTK's polydata fragment shader (at //VTK::Normal::Dec); the
// rest of that shader (lighting, coloring, depth peeling, picking) is VTK's.
// Every fragment of a sub-segment's bounding box intersects its view ray with
// the spheres swept along the sub-segment (svIntersectSubSegment), or, for
// the segments and sub-segments the vertex stage found straight (mode 1 and
// 2), with the round cone on their chord in closed form
// (svIntersectRoundCone); a miss discards the fragment, a hit gives the
// exact depth, the normal (from the sphere center to the hit point) and the
// curve parameter for the color spline.

flat in vec4 tubeQ0VSOutput; // quadratic sub-segment, view coordinates
flat in vec4 tubeQ1VSOutput;
flat in vec4 tubeQ2VSOutput;
flat in ivec4 tubeInfoVSOutput; // first node, sub-segment, tube, flags | mode << 2
flat in vec4 tubeCut0VSOutput;  // translucent: the planes bounding the rectangle's part
flat in vec4 tubeCut1VSOutput;

uniform mat4 VCDCMatrix;
uniform int subSegments;
uniform int rootIterations;
uniform int rootSamples;

//SV::SplineTubeMath::Dec

// Casts the view ray through `fragmentVC` (a point of the bounding box).
// Returns false on a miss; otherwise the hit point and unit normal (view
// coordinates) and the cubic segment's curve parameter t in [0, 1].
bool tubeRayCast(vec3 fragmentVC, out vec3 hitVC, out vec3 normalVC, out float t)
{
  vec3 origin;
  vec3 dir;
  if (cameraParallel != 0)
  {
    origin = vec3(fragmentVC.x, fragmentVC.y, 0.0);
    dir = vec3(0.0, 0.0, -1.0);
  }
  else
  {
    origin = vec3(0.0);
    dir = normalize(fragmentVC);
  }
  int mode = tubeInfoVSOutput.w >> 2;
  float k = float(tubeInfoVSOutput.y);
  SvHit hit;
  vec4 center;
  if (mode == 3)
  {
    // Two straight sub-segments: the cones (q0, q1) and (q1, q2).
    hit = svIntersectRoundCone(origin, dir, tubeQ0VSOutput, tubeQ1VSOutput);
    SvHit second = svIntersectRoundCone(origin, dir, tubeQ1VSOutput, tubeQ2VSOutput);
    center = mix(tubeQ0VSOutput, tubeQ1VSOutput, hit.l);
    if (second.inside || (second.hit && (!hit.hit || second.distance < hit.distance)))
    {
      hit = second;
      center = mix(tubeQ1VSOutput, tubeQ2VSOutput, hit.l);
      k += 1.0;
    }
    hit.hit = hit.hit && !hit.inside;
  }
  else if (mode != 0)
  {
    hit = svIntersectRoundCone(origin, dir, tubeQ0VSOutput, tubeQ2VSOutput);
    center = mix(tubeQ0VSOutput, tubeQ2VSOutput, hit.l);
  }
  else
  {
#ifdef SV_STRAIGHT_CHUNKS
    // (the mapper draws here only chunks whose segments the vertex stage
    // finds straight, with a margin: never reached; the chord's cone if it were)
    hit = svIntersectRoundCone(origin, dir, tubeQ0VSOutput, tubeQ2VSOutput);
    center = mix(tubeQ0VSOutput, tubeQ2VSOutput, hit.l);
#else
    hit = svIntersectSubSegment(origin, dir, tubeQ0VSOutput, tubeQ1VSOutput, tubeQ2VSOutput,
      rootIterations, rootSamples);
    center = svQuadratic(tubeQ0VSOutput, tubeQ1VSOutput, tubeQ2VSOutput, hit.l);
#endif
  }
  if (!hit.hit)
  {
    return false;
  }
  hitVC = origin + hit.distance * dir;
  // Translucent: neighbouring rectangles share their end sphere, so a pixel
  // near a joint is hit by both, once on the tube's surface and once inside
  // it. Depth testing hides the inner hit when opaque; translucent, it would
  // be one more layer. Each rectangle keeps only the hits between its two
  // cut planes (normal to the curve at its ends; vtkRayCastTubeVS.glsl), so
  // every point of the tube belongs to exactly one rectangle.
  if (dot(tubeCut0VSOutput, vec4(hitVC, 1.0)) < 0.0 ||
    dot(tubeCut1VSOutput, vec4(hitVC, 1.0)) <= 0.0)
  {
    return false;
  }
  vec3 n = hitVC - center.xyz;
  float len = length(n);
  normalVC = len > 0.0 ? n / len : -dir;
  t = mode == 2 ? hit.l : (k + hit.l) / float(subSegments);
  return true;
}
