#version 120
// Reads two uniforms its script never sets (tests/data/web/unset.glib).
uniform float uStripes;
uniform float uBright;
uniform vec3 uTint;
varying vec2 vST;

void main()
{
    float s = step(0.5, fract(vST.s * uStripes));
    gl_FragColor = vec4(uBright * (vec3(s, 0.6 * s, 0.25) + uTint), 1.);
}
