#version 330 compatibility

// The overflow's blur: the separable 9-tap Gaussian (LearnOpenGL's published
// weights, summing to 0.9999994) with its taps spread uSpread texels apart.
// uSpread = 1 is the chapter's kernel exactly (reach 4 texels); a larger spread
// reaches further for the same 9 taps, reading between texels (bilinear) where
// uSpread is fractional, and leaves gaps (rings) on sharp features when large.
uniform sampler2D ImageUnit;
uniform int uHorizontal;        // 1: along s, 0: along t
uniform float uSpread;          // texels between taps

in vec2 vST;

const float weight[5] = float[]( 0.227027, 0.1945946, 0.1216216, 0.054054, 0.016216 );

void main( )
{
    vec2 texel = 1. / vec2( textureSize( ImageUnit, 0 ) );
    vec2 step = uSpread * ( uHorizontal != 0 ? vec2( texel.x, 0. ) : vec2( 0., texel.y ) );
    vec3 result = texture( ImageUnit, vST ).rgb * weight[0];
    for( int i = 1; i < 5; ++i )
    {
        result += texture( ImageUnit, vST + float(i) * step ).rgb * weight[i];
        result += texture( ImageUnit, vST - float(i) * step ).rgb * weight[i];
    }
    gl_FragColor = vec4( result, 1. );
}
