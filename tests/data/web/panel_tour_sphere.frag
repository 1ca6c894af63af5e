#version 120
// The panel tour's sphere (tests/data/web/panel_tour.glib): every uniform
// it reads is one kind of panel control, so each click changes the picture.
uniform float uStripes;
uniform int uRings;
uniform bool uInvert;
uniform vec4 uTint;
uniform float uBright;  // never set by the script: the panel offers it
uniform sampler2D PatternUnit;
varying vec2 vST;

void main()
{
    vec3 c = texture2D(PatternUnit, vST * float(uRings)).rgb * uTint.rgb;
    c = mix(c, 0.5 * c, step(0.5, fract(vST.t * uStripes))) + uBright;
    if (uInvert) c = 1. - c;
    gl_FragColor = vec4(c, 1.);
}
