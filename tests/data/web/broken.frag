varying vec2 vST;
uniform float uStripes;

void main()
{
    float s = step(.5, fract(vST.s * uStripes));
    gl_FragColor = vec4(s, stripe, 0., 1.);
}
