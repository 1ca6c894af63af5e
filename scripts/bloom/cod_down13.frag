#version 330 compatibility

// Jimenez 2014, "Next Generation Post Processing in Call of Duty: Advanced Warfare",
// 'Downsampling': 13 bilinear taps around the target texel's centre p in the source
// (twice the size), at offsets in SOURCE texels:
//      a . b . c
//      . j . k .
//      d . e . f
//      . l . m .
//      g . h . i
// five 2x2 boxes, each averaged: the centre box (j k l m) weighs 0.5, the four
// corner boxes (a b d e), (b c e f), (d e g h), (e f h i) 0.125 each.
// uKaris (the first downsample only): within each box the taps are averaged with
// weights 1 / (1 + luma) (the partial Karis average against fireflies).
// src/reference: codDownsample13(img, karis).
uniform sampler2D ImageUnit;
uniform bool uKaris;

in vec2 vST;

float luma( vec3 c ) { return max( dot( c, vec3( 0.2126, 0.7152, 0.0722 ) ), 0. ); }

vec3 box( vec3 t0, vec3 t1, vec3 t2, vec3 t3 )
{
    if( !uKaris )
        return 0.25 * ( t0 + t1 + t2 + t3 );
    float k0 = 1. / ( 1. + luma( t0 ) );
    float k1 = 1. / ( 1. + luma( t1 ) );
    float k2 = 1. / ( 1. + luma( t2 ) );
    float k3 = 1. / ( 1. + luma( t3 ) );
    return ( k0 * t0 + k1 * t1 + k2 * t2 + k3 * t3 ) / ( k0 + k1 + k2 + k3 );
}

void main( )
{
    vec2 texel = 1. / vec2( textureSize( ImageUnit, 0 ) );
    #define S(dx, dy) texture( ImageUnit, vST + vec2( dx, dy ) * texel ).rgb
    vec3 a = S( -2., -2. ), b = S( 0., -2. ), c = S( 2., -2. );
    vec3 d = S( -2.,  0. ), e = S( 0.,  0. ), f = S( 2.,  0. );
    vec3 g = S( -2.,  2. ), h = S( 0.,  2. ), i = S( 2.,  2. );
    vec3 j = S( -1., -1. ), k = S( 1., -1. );
    vec3 l = S( -1.,  1. ), m = S( 1.,  1. );
    #undef S
    vec3 result = 0.5   * box( j, k, l, m )
                + 0.125 * box( a, b, d, e )
                + 0.125 * box( b, c, e, f )
                + 0.125 * box( d, e, g, h )
                + 0.125 * box( e, f, h, i );
    gl_FragColor = vec4( result, 1. );
}
