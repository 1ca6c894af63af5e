#version 330 compatibility
// A sampler2D and a samplerCube the script sets to one unit: OpenGL refuses
// to draw with this program (tests/glman/unit_targets_test.cpp).
uniform sampler2D uTex;
uniform samplerCube uSky;
in vec2 vST;
void main() {
    gl_FragColor = vec4(texture2D(uTex, vST).rgb + textureCube(uSky, vec3(1., 0., 0.)).rgb, 1.);
}
