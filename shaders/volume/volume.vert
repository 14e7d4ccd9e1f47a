#version 330 core
// Shadow volumes: positions pass through in world space; extrude.geom builds the volume.
layout(location = 0) in vec3 a_position;
out vec3 v_world_position;
void main() { v_world_position = a_position; }
