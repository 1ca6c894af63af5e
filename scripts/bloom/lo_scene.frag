#version 330 compatibility

// LearnOpenGL "Bloom", the lighting pass: the HDR colour to target 0 and, in the
// same pass (multiple render targets), the fragments brighter than a threshold to
// target 1. Here the "lighting" is the HDR picture itself.
uniform sampler2D HdrUnit;
uniform float uThreshold;      // LearnOpenGL: 1.0

in vec2 vST;

layout(location = 0) out vec4 FragColor;
layout(location = 1) out vec4 BrightColor;

void main( )
{
    vec3 lighting = texture( HdrUnit, vST ).rgb;
    FragColor = vec4( lighting, 1. );
    // Rec. 709 luminance, as the chapter's dot(FragColor.rgb, vec3(0.2126, 0.7152, 0.0722))
    float brightness = dot( FragColor.rgb, vec3( 0.2126, 0.7152, 0.0722 ) );
    if( brightness > uThreshold )
        BrightColor = vec4( FragColor.rgb, 1. );
    else
        BrightColor = vec4( 0., 0., 0., 1. );
}
