#version 330 compatibility

// "Overflow light" bloom (seed 002): the lighting pass writes two targets at once.
// Target 0 is the colour as before; into an RGBA8 (UNORM) target it is clamped to 1.
// Target 1 holds how far the colour went over 1: max(colour - 1, 0), times a scale
// ("could scale if you want to allow more range outside of just 1 to 2").
uniform sampler2D HdrUnit;
uniform float uOverflowScale;

in vec2 vST;

layout(location = 0) out vec4 color;
layout(location = 1) out vec4 bloom;

void main( )
{
    vec3 finalColor = texture( HdrUnit, vST ).rgb;   // surface colour after all lighting
    color = vec4( finalColor, 1. );
    vec3 overflow = max( finalColor - vec3( 1. ), vec3( 0. ) );
    bloom = vec4( uOverflowScale * overflow, 1. );
}
