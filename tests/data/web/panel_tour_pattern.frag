#version 120
// The panel tour's render target: stripes (tests/data/web/panel_tour.glib).
uniform float uStripes;
varying vec2 vST;

void main()
{
    float s = step(0.5, fract(vST.s * uStripes));
    gl_FragColor = vec4(s, 0.5 * s, 0.2, 1.);
}
