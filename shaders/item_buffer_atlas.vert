#version 330 core
// The five faces of a hemicube in one instanced draw: instance f draws the
// patches through face f's camera, then moves the picture into the face's rectangle of the
// atlas. The four clip distances cut it at the sides of the face's own frustum, where the
// face's viewport would have ended it, so no face spills into its neighbour.
layout(location = 0) in vec3 a_position;

const int kMaxFaces = 5;  // PatchItems::kMaxAtlasFaces
uniform mat4 u_face_view_projection[kMaxFaces];
uniform mat4 u_face_to_atlas[kMaxFaces];

void main() {
  vec4 clip = u_face_view_projection[gl_InstanceID] * vec4(a_position, 1.0);
  gl_ClipDistance[0] = clip.w - clip.x;
  gl_ClipDistance[1] = clip.w + clip.x;
  gl_ClipDistance[2] = clip.w - clip.y;
  gl_ClipDistance[3] = clip.w + clip.y;
  gl_Position = u_face_to_atlas[gl_InstanceID] * clip;
}
