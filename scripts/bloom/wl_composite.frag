#version 330 compatibility

// Sascha Willems' Vulkan "bloom", third pass on the screen: the scene, then the
// horizontal blur of the (vertically blurred) FB_DIM target blended on top with
// additive blending (ONE, ONE). GLIB has no blend command, so this one shader
// does both: the scene texel plus the seed's horizontal gaussblur of BlurUnit.
// The seed's scene is LDR Phong shading; here the HDR picture, clamped to 1 as an
// 8-bit screen shows it. uShowScene false leaves the blur alone.
uniform sampler2D SceneUnit;
uniform sampler2D BlurUnit;
uniform float uBlurScale;
uniform float uBlurStrength;
uniform bool uShowScene;

in vec2 vST;

void main( )
{
    float weight[5];
    weight[0] = 0.227027;
    weight[1] = 0.1945946;
    weight[2] = 0.1216216;
    weight[3] = 0.054054;
    weight[4] = 0.016216;

    // gaussblur.frag with blurdirection == 1 (horizontal), on the small target
    vec2 tex_offset = 1. / vec2( textureSize( BlurUnit, 0 ) ) * uBlurScale;
    vec3 result = texture( BlurUnit, vST ).rgb * weight[0];
    for( int i = 1; i < 5; ++i )
    {
        result += texture( BlurUnit, vST + vec2( tex_offset.x * float(i), 0. ) ).rgb * weight[i] * uBlurStrength;
        result += texture( BlurUnit, vST - vec2( tex_offset.x * float(i), 0. ) ).rgb * weight[i] * uBlurStrength;
    }

    vec3 scene = uShowScene ? min( texture( SceneUnit, vST ).rgb, vec3( 1. ) ) : vec3( 0. );
    gl_FragColor = vec4( scene + result, 1. );      // additive blend, ONE + ONE
}
