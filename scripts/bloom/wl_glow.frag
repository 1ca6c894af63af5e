#version 330 compatibility

// Sascha Willems' Vulkan "bloom", first pass: only the glowing parts (the seed draws
// a separate glow mesh, models.ufoGlow, with its vertex colours) into a small
// FB_DIM x FB_DIM target of FB_COLOR_FORMAT VK_FORMAT_R8G8B8A8_UNORM. Here the glowing
// parts are the scene's emitters: the texels with luminance above 1, in their own
// colour; the RGBA8 target clamps them to 1 as the seed's UNORM target would.
// uTestFlat replaces the glow by a flat grey 0.25, to measure what the blur does
// to a constant (see docs/bloom.md, "Willems").
uniform sampler2D HdrUnit;
uniform bool uTestFlat;

in vec2 vST;

void main( )
{
    vec3 c = texture( HdrUnit, vST ).rgb;
    float luminance = dot( c, vec3( 0.2126, 0.7152, 0.0722 ) );
    vec3 glow = luminance > 1. ? c : vec3( 0. );
    if( uTestFlat )
        glow = vec3( 0.25 );
    gl_FragColor = vec4( glow, 1. );
}
