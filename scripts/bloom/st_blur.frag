#version 330 compatibility

// Sol Trader's blur: three bilinear lookups, 5/16 at -offset, 6/16 at the centre,
// 5/16 at +offset, along one axis (uDir). The seed passes offset = 1.2 / width
// in texture coordinates; here uOffset is in texels of the buffer being blurred
// (src/reference: solTraderTaps(1.2)).
uniform sampler2D ImageUnit;
uniform vec2 uDir;              // [1 0] horizontal, [0 1] vertical
uniform float uOffset;          // texels

in vec2 vST;

void main( )
{
    vec2 offset = uOffset * uDir / vec2( textureSize( ImageUnit, 0 ) );
    vec4 c = vec4( 0. );
    c += 5.0 * texture( ImageUnit, vST - offset );
    c += 6.0 * texture( ImageUnit, vST );
    c += 5.0 * texture( ImageUnit, vST + offset );
    gl_FragColor = vec4( ( c / 16.0 ).rgb, 1. );
}
