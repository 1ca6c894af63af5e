
#version 330 compatibility
uniform sampler2D ImageUnit;
uniform int uHalfSize;
in vec2 vST;

void main( )
{
    ivec2 ires = textureSize( ImageUnit, 0 );
    float ds = 1. / float( ires.s );
    float dt = 1. / float( ires.t );

    int halfSize = uHalfSize | 01;          // be sure it's an odd number
    vec3 rgbSum = vec3( 0., 0., 0. );
    float maxDistance = length( vec2( float(halfSize), float(halfSize) ) );
    maxDistance += 1.;      // don't want a zero weight
    float weightSum = 0.;

    for( int i = -halfSize; i <= halfSize; i++ )
    {
        float di = float(i);
        for( int j = -halfSize; j <= halfSize; j++ )
        {
            float dj = float(j);
            vec2 st = vST + vec2( di*ds, dj*dt );
            float weight = maxDistance - length( vec2(di,dj) );
            rgbSum += weight*texture(ImageUnit,st).rgb;
            weightSum += weight;
        }
    }
    rgbSum /= weightSum;
    gl_FragColor = vec4( rgbSum, 1. );
}

