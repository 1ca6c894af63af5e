#version 330 compatibility

// Dual Kawase (Marius Bjorge, "Bandwidth-Efficient Rendering", SIGGRAPH 2015),
// downsample to half size: (4 s(p) + s(p +- h, p +- h) on the 4 diagonals) / 8,
// h = halfpixel * offset, halfpixel = 0.5 / source size (h = 0.5 * uOffset SOURCE
// texels). uOffset = 1 is a plain 2x2 box. src/reference: kawaseDown.
uniform sampler2D ImageUnit;
uniform float uOffset;

in vec2 vST;

void main( )
{
    vec2 halfpixel = 0.5 / vec2( textureSize( ImageUnit, 0 ) );
    vec2 h = halfpixel * uOffset;
    vec3 sum = texture( ImageUnit, vST ).rgb * 4.;
    sum += texture( ImageUnit, vST - h ).rgb;
    sum += texture( ImageUnit, vST + h ).rgb;
    sum += texture( ImageUnit, vST + vec2( h.x, -h.y ) ).rgb;
    sum += texture( ImageUnit, vST - vec2( h.x, -h.y ) ).rgb;
    gl_FragColor = vec4( sum / 8., 1. );
}
