// The surfaces' material when no lab gives one ("lab/material.glsl"): the vertex colour.
vec3 surface_albedo(vec3 p, vec3 n, vec3 color) { return color; }
