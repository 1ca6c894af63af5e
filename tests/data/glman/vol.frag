#version 330 compatibility
// A slice through the 3-D texture at r = uR.
uniform sampler3D uVol;
uniform float uR;
in vec2 vST;
void main() {
    gl_FragColor = vec4(texture3D(uVol, vec3(vST, uR)).rgb, 1.);
}
