#version 330 compatibility
// Each uniform is given a form that does not fit its type.
uniform float uFlag;    // given <true>
uniform vec3 uTint;     // given a range <0 .5 1>
uniform float uGrey;    // given a colour {1 0 0}
in vec2 vST;
void main() {
    if (vST.s < 1. / 3.) gl_FragColor = vec4(uFlag, 0., 0., 1.);
    else if (vST.s < 2. / 3.) gl_FragColor = vec4(uTint, 1.);
    else gl_FragColor = vec4(uGrey, uGrey, uGrey, 1.);
}
