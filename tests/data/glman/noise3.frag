#version 330 compatibility
// glman's marble-ish use of the 3-D noise: the four octaves summed.
uniform sampler3D Noise3;
in vec3 vMC;
void main() {
    vec4 n = texture3D(Noise3, 0.5 * vMC + 0.5);
    float sum = (n.r + n.g + n.b + n.a - 1.) / 2.;
    gl_FragColor = vec4(sum, sum * 0.8, 1. - sum, 1.);
}
