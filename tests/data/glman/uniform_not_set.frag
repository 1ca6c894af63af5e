#version 330 compatibility
// Uniforms the script gives values that cannot be set (uniform_not_set.glib):
// both stay 0, so the left half is green and the right half blue.
uniform uint uCount;    // given the range <0 3 5>: not set
uniform uvec2 uPair;    // given [1 2]: not set
in vec2 vST;
void main() {
    if (vST.s < .5) gl_FragColor = vec4(float(uCount) / 5., 1., 0., 1.);
    else gl_FragColor = vec4(float(uPair.x), float(uPair.y) / 2., 1., 1.);
}
