#version 330 compatibility

// Dual Kawase upsample to twice the size: taps at +-2h along each axis (weight 1)
// and at the 4 diagonals +-h (weight 2), / 12; h = halfpixel * offset of the SOURCE
// (smaller) texture. src/reference: kawaseUp.
uniform sampler2D ImageUnit;
uniform float uOffset;

in vec2 vST;

void main( )
{
    vec2 halfpixel = 0.5 / vec2( textureSize( ImageUnit, 0 ) );
    vec2 h = halfpixel * uOffset;
    vec3 sum = texture( ImageUnit, vST + vec2( -h.x * 2., 0. ) ).rgb;
    sum += texture( ImageUnit, vST + vec2( -h.x, h.y ) ).rgb * 2.;
    sum += texture( ImageUnit, vST + vec2( 0., h.y * 2. ) ).rgb;
    sum += texture( ImageUnit, vST + vec2( h.x, h.y ) ).rgb * 2.;
    sum += texture( ImageUnit, vST + vec2( h.x * 2., 0. ) ).rgb;
    sum += texture( ImageUnit, vST + vec2( h.x, -h.y ) ).rgb * 2.;
    sum += texture( ImageUnit, vST + vec2( 0., -h.y * 2. ) ).rgb;
    sum += texture( ImageUnit, vST + vec2( -h.x, -h.y ) ).rgb * 2.;
    gl_FragColor = vec4( sum / 12., 1. );
}
