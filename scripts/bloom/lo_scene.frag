#version 330 compatibility

// LearnOpenGL "Bloom", the lighting pass: the HDR colour to target 0 and, in the
// same pass (multiple render targets), the fragments brighter than a threshold to
// target 1. Here the "lighting" is the HDR picture itself.
uniform sampler2D HdrUnit;
uniform float uThreshold;      // LearnOpenGL: 1.0
uniform bool  uSanitize;       // Glimmer: keep a NaN or Inf texel out of the blur

in vec2 vST;

layout(location = 0) out vec4 FragColor;
layout(location = 1) out vec4 BrightColor;

void main( )
{
    vec3 lighting = texture( HdrUnit, vST ).rgb;
    FragColor = vec4( lighting, 1. );
    // Rec. 709 luminance, as the chapter's dot(FragColor.rgb, vec3(0.2126, 0.7152, 0.0722))
    float brightness = dot( FragColor.rgb, vec3( 0.2126, 0.7152, 0.0722 ) );
    vec3 bright = brightness > uThreshold ? FragColor.rgb : vec3( 0. );
    // One NaN in the bright pass would spread through every blur tap that
    // reads it (a 9x9 cross per pair); one Inf likewise. Sanitize drops
    // such texels and caps the rest at the largest half float.
    if( uSanitize )
        bright = ( any( isnan( bright ) ) || any( isinf( bright ) ) ) ? vec3( 0. ) : min( bright, vec3( 65504. ) );
    BrightColor = vec4( bright, 1. );
}
