#version 330 compatibility

// Jimenez 2014, 'Upsampling': the 3x3 tent, (1 2 1) x (1 2 1) / 16, of the smaller
// level at p + uRadius * (dx, dy) SOURCE (smaller) texels, added to this level's
// own downsample ("upsample and accumulate"). src/reference: codUpsampleTent.
uniform sampler2D SmallUnit;    // the accumulated level below (half this size)
uniform sampler2D MipUnit;      // this level's downsample
uniform float uRadius;

in vec2 vST;

vec3 tent( sampler2D s, vec2 st, float radius )
{
    vec2 r = radius / vec2( textureSize( s, 0 ) );
    vec3 sum = vec3( 0. );
    sum += 1. * texture( s, st + vec2( -r.x, -r.y ) ).rgb;
    sum += 2. * texture( s, st + vec2(  0.,  -r.y ) ).rgb;
    sum += 1. * texture( s, st + vec2(  r.x, -r.y ) ).rgb;
    sum += 2. * texture( s, st + vec2( -r.x,  0.  ) ).rgb;
    sum += 4. * texture( s, st                      ).rgb;
    sum += 2. * texture( s, st + vec2(  r.x,  0.  ) ).rgb;
    sum += 1. * texture( s, st + vec2( -r.x,  r.y ) ).rgb;
    sum += 2. * texture( s, st + vec2(  0.,   r.y ) ).rgb;
    sum += 1. * texture( s, st + vec2(  r.x,  r.y ) ).rgb;
    return sum / 16.;
}

void main( )
{
    vec3 result = texture( MipUnit, vST ).rgb + tent( SmallUnit, vST, uRadius );
    gl_FragColor = vec4( result, 1. );
}
