#version 330 compatibility

// Sol Trader "How to quickly add bloom" (seed 003), step 1: the original image to
// one buffer and, in the same pass, the glowing parts to a glow buffer
// (gl_FragData[0], gl_FragData[1]). The glowing parts are the scene's emitters:
// the texels with luminance above uGlowThreshold, times uGlowAmount (the seed adds
// "9% of the GUI's colour" for a faint glow; emitters glow fully).
uniform sampler2D HdrUnit;
uniform float uGlowThreshold;
uniform float uGlowAmount;

in vec2 vST;

void main( )
{
    vec4 colour = vec4( texture( HdrUnit, vST ).rgb, 1. );
    float luminance = dot( colour.rgb, vec3( 0.2126, 0.7152, 0.0722 ) );
    gl_FragData[0] = colour;
    gl_FragData[1] = luminance > uGlowThreshold ? vec4( colour.rgb * uGlowAmount, 1. ) : vec4( 0., 0., 0., 1. );
}
