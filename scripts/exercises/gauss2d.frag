#version 330 compatibility

// Exercise 1: superblur's loop with Gaussian weights instead of the cone.
// Weight exp(-(i^2 + j^2) / (2 sigma^2)), over a square of half-size ceil(3 sigma)
// (beyond 3 sigma a weight is under 1 % of the centre's), normalised by the sum.
uniform sampler2D ImageUnit;
uniform float uSigma;           // in texels of ImageUnit

in vec2 vST;

void main( )
{
    vec2 texel = 1. / vec2( textureSize( ImageUnit, 0 ) );
    int halfSize = int( ceil( 3. * uSigma ) );
    float k = -1. / ( 2. * uSigma * uSigma );
    vec3 sum = vec3( 0. );
    float weightSum = 0.;
    for( int i = -halfSize; i <= halfSize; i++ )
    {
        for( int j = -halfSize; j <= halfSize; j++ )
        {
            float weight = exp( k * float( i*i + j*j ) );
            sum += weight * texture( ImageUnit, vST + vec2( i, j ) * texel ).rgb;
            weightSum += weight;
        }
    }
    gl_FragColor = vec4( sum / weightSum, 1. );
}
