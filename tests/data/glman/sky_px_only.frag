#version 330 compatibility
// The cube map's +x face, wherever the quad is (tests/glman/unit_targets_test.cpp).
uniform samplerCube uSky;
void main() {
    gl_FragColor = vec4(textureCube(uSky, vec3(1., 0., 0.)).rgb, 1.);
}
