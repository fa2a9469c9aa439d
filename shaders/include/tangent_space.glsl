// Tangent frames per fragment: the interpolated normal and tangent are re-orthonormalised
// (Gram-Schmidt) and the bitangent rebuilt as cross(N, T) * w, as reference 004 stores it.

struct TangentFrame {
  vec3 tangent;
  vec3 bitangent;
  vec3 normal;
};

TangentFrame buildTangentFrame(vec3 worldNormal, vec4 worldTangent, bool frontFacing) {
  TangentFrame frame;
  frame.normal = normalize(worldNormal);
  vec3 t = worldTangent.xyz - dot(worldTangent.xyz, frame.normal) * frame.normal;
  frame.tangent = dot(t, t) > 1e-20 ? normalize(t) : vec3(1.0, 0.0, 0.0);
  frame.bitangent = cross(frame.normal, frame.tangent) * worldTangent.w;
  // Seen from behind (an open mesh such as the plane), light the side that faces the viewer.
  if (!frontFacing) frame.normal = -frame.normal;
  return frame;
}

// Reference 004: Vt = (dot(T, V), dot(B, V), dot(N, V)); the order T, B, N matters.
vec3 toTangentSpace(TangentFrame frame, vec3 worldVector) {
  return vec3(dot(frame.tangent, worldVector), dot(frame.bitangent, worldVector),
              dot(frame.normal, worldVector));
}

// The inverse: the frame is orthonormal, so its transpose.
vec3 fromTangentSpace(TangentFrame frame, vec3 tangentVector) {
  return frame.tangent * tangentVector.x + frame.bitangent * tangentVector.y +
         frame.normal * tangentVector.z;
}
