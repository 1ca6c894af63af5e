#version 330 compatibility
// One bad texel: 0/0 where the quad's s and t are both past 0.9.
uniform float uZero;
in vec2 vST;
void main() {
    float v = (vST.s > 0.9 && vST.t > 0.9) ? uZero / uZero : 0.5;
    gl_FragColor = vec4(v, v, v, 1.0);
}
