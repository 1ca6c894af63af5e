#version 330 compatibility
// The normal as the vertex colour: Flat and Smooth decide how it spreads.
void main() {
    gl_FrontColor = vec4(0.5 + 0.5 * normalize(gl_Normal), 1.);
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
