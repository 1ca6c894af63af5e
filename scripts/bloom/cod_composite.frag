#version 330 compatibility

// Jimenez 2014 composite: the last tent upsample to full size, divided by the
// number of levels (the chain adds them; the mean keeps a constant, as
// src/reference codBloomChain does), blended with the scene by a lerp
// (the slides mix bloom in, they do not threshold), then exposure tone mapping
// 1 - exp(-c * exposure) and gamma, as learnopengl.glib.
uniform sampler2D SceneUnit;
uniform sampler2D BloomUnit;    // the accumulated half-size level
uniform float uLevels;
uniform float uRadius;
uniform float uBloomMix;
uniform float uExposure;
uniform float uGamma;

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
    vec3 scene = texture( SceneUnit, vST ).rgb;
    vec3 bloom = tent( BloomUnit, vST, uRadius ) / uLevels;
    vec3 hdr = mix( scene, bloom, uBloomMix );
    vec3 result = vec3( 1. ) - exp( -hdr * uExposure );
    result = pow( result, vec3( 1. / uGamma ) );
    gl_FragColor = vec4( result, 1. );
}
