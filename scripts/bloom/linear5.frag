#version 330 compatibility

// gauss9.frag's kernel with bilinear tap merging (Rakos, "Efficient Gaussian
// blur with linear sampling", 2010): each pair of neighbouring taps becomes one
// fetch between them, weighted by their sum, so 5 fetches give the 9 taps.
// Exact only where the texture is linear between texels (GL_LINEAR); the
// tradeoff measures what that costs against gauss9's CPU reference.
uniform sampler2D ImageUnit;
uniform int uHorizontal;        // 1: along s, 0: along t

in vec2 vST;

const float offset[3] = float[]( 0.0, 1.3846153846, 3.2307692308 );
const float weight[3] = float[]( 0.227027, 0.3162162, 0.07027 );

void main( )
{
    vec2 tex_offset = 1. / vec2( textureSize( ImageUnit, 0 ) );   // one texel
    vec2 step = uHorizontal != 0 ? vec2( tex_offset.x, 0. ) : vec2( 0., tex_offset.y );
    vec3 result = texture( ImageUnit, vST ).rgb * weight[0];
    for( int i = 1; i < 3; ++i )
    {
        result += texture( ImageUnit, vST + offset[i] * step ).rgb * weight[i];
        result += texture( ImageUnit, vST - offset[i] * step ).rgb * weight[i];
    }
    gl_FragColor = vec4( result, 1. );
}
