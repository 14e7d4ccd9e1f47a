#version 330 core
// What a point light's cube map stores: the distance from the light to the nearest surface, in world
// units. The depth buffer only picks the nearest surface; its perspective depth is not linear in
// distance and differs from face to face, so it is not what the lit pass compares against.
in vec3 v_world_position;
uniform vec3 u_light_position;
layout(location = 0) out float o_distance;

void main() { o_distance = length(v_world_position - u_light_position); }
