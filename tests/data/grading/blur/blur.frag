#version 330 compatibility

// A 2-D Gaussian over a square of half-size uHalfSize texels, sigma =
// uHalfSize / 2 (the square ends at 2 sigma), normalised by the sum of the
// weights. Every tap is clamped to the texture's texels: a glow stops at the
// edge instead of wrapping round to the other side (GL_REPEAT).
uniform sampler2D ImageUnit;
uniform int uHalfSize;

in vec2 vST;

void main( )
{
    vec2 texel = 1. / vec2( textureSize( ImageUnit, 0 ) );
    float sigma = 0.5 * float( uHalfSize );
    float k = -1. / ( 2. * sigma * sigma );
    vec3 sum = vec3( 0. );
    float weightSum = 0.;
    for( int i = -uHalfSize; i <= uHalfSize; i++ )
    {
        for( int j = -uHalfSize; j <= uHalfSize; j++ )
        {
            float weight = exp( k * float( i*i + j*j ) );
            vec2 st = clamp( vST + vec2( i, j ) * texel, 0.5 * texel, 1. - 0.5 * texel );
            sum += weight * texture( ImageUnit, st ).rgb;
            weightSum += weight;
        }
    }
    gl_FragColor = vec4( sum / weightSum, 1. );
}
