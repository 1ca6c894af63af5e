#version 330 compatibility

// Exercises 3 to 5: the Gaussian of gauss2d.frag cut in two. One pass blurs
// along s (uHorizontal 1), the next along t (uHorizontal 0): 2 (2r + 1) taps
// instead of (2r + 1)^2, the same picture, because exp(-(i^2 + j^2) / 2s^2) is
// exp(-i^2 / 2s^2) times exp(-j^2 / 2s^2).
// uClamp (exercise 4): keep every tap inside the texture, as CLAMP_TO_EDGE
// would; off, Glimmer's GL_REPEAT wraps taps round to the other edge.
uniform sampler2D ImageUnit;
uniform float uSigma;           // in texels of ImageUnit
uniform int   uHorizontal;      // 1: along s, 0: along t
uniform bool  uClamp;

in vec2 vST;

void main( )
{
    vec2 texel = 1. / vec2( textureSize( ImageUnit, 0 ) );
    vec2 step = uHorizontal != 0 ? vec2( texel.x, 0. ) : vec2( 0., texel.y );
    int halfSize = int( ceil( 3. * uSigma ) );
    float k = -1. / ( 2. * uSigma * uSigma );
    vec3 sum = vec3( 0. );
    float weightSum = 0.;
    for( int i = -halfSize; i <= halfSize; i++ )
    {
        vec2 st = vST + float( i ) * step;
        if( uClamp )
            st = clamp( st, 0.5 * texel, 1. - 0.5 * texel );
        float weight = exp( k * float( i*i ) );
        sum += weight * texture( ImageUnit, st ).rgb;
        weightSum += weight;
    }
    gl_FragColor = vec4( sum / weightSum, 1. );
}
