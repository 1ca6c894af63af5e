#version 330 compatibility
// More uniforms given forms that do not fit their types (uniform_forms.glib
// has the first three), each drawn in a sixth of the picture.
uniform vec3 uOn;       // given <true>: every component 1
uniform int uN;         // given the range <0 2.7 5>: rounded to 3
uniform mat2 uM;        // given the range <0 .5 1>: .5 times the identity
uniform vec3 uPart;     // given [.2 .4]: the missing component 0
uniform vec2 uExtra;    // given [.2 .4 .6 .8]: the extra two dropped
uniform float uW[3];    // given [.2 .4 .6]: an array, found under its own name
in vec2 vST;
void main() {
    float s = vST.s * 6.;
    if (s < 1.) gl_FragColor = vec4(uOn, 1.);
    else if (s < 2.) gl_FragColor = vec4(float(uN) / 5., 0., 0., 1.);
    else if (s < 3.) gl_FragColor = vec4(uM[0][0], uM[0][1], uM[1][1], 1.);
    else if (s < 4.) gl_FragColor = vec4(uPart, 1.);
    else if (s < 5.) gl_FragColor = vec4(uExtra, 0., 1.);
    else gl_FragColor = vec4(uW[0], uW[1], uW[2], 1.);
}
