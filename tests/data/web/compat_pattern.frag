varying vec2 vST;
uniform float uStripes;

void main()
{
    float s = step(.5, fract(vST.s * uStripes));
    float t = step(.5, fract(vST.t * 3.));
    gl_FragColor = vec4(s, t, .5 * s * t, 1.);
}
