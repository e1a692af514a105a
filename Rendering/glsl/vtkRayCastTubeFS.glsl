// Ray-cast spline tubes (Salm §3.2), fragment-stage declarations.
//
// Inserted into VTK's polydata fragment shader (at //VTK::Normal::Dec); the
// rest of that shader (lighting, coloring, depth peeling, picking) is VTK's.
// Every fragment of a sub-segment's bounding box intersects its view ray with
// the spheres swept along the sub-segment (svIntersectSubSegment); a miss
// discards the fragment, a hit gives the exact depth, the normal (from the
// sphere center to the hit point) and the curve parameter for the color spline.

flat in vec4 tubeQ0VSOutput; // quadratic sub-segment, view coordinates
flat in vec4 tubeQ1VSOutput;
flat in vec4 tubeQ2VSOutput;
flat in ivec4 tubeInfoVSOutput; // first node, sub-segment, tube, flags

uniform mat4 VCDCMatrix;
uniform int subSegments;
uniform int rootIterations;
uniform int rootSamples;

//VTK::SplineTubeMath::Dec

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
  SvHit hit = svIntersectSubSegment(origin, dir, tubeQ0VSOutput, tubeQ1VSOutput, tubeQ2VSOutput,
    rootIterations, rootSamples);
  if (!hit.hit)
  {
    return false;
  }
  hitVC = origin + hit.distance * dir;
  vec4 center = svQuadratic(tubeQ0VSOutput, tubeQ1VSOutput, tubeQ2VSOutput, hit.l);
  vec3 n = hitVC - center.xyz;
  float len = length(n);
  normalVC = len > 0.0 ? n / len : -dir;
  t = (float(tubeInfoVSOutput.y) + hit.l) / float(subSegments);
  return true;
}
