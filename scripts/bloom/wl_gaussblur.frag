#version 330 compatibility

// Sascha Willems' Vulkan "bloom", gaussblur.frag, as published: the centre tap
// weight[0], then the taps at +-i * blurScale texels times weight[i] * blurStrength.
// Only the side taps are scaled by blurStrength, so the kernel sums to
// w0 + 2 s (w1 + w2 + w3 + w4), 1.3864856 at s = 1.5, not 1 (docs/bloom.md).
// blurdirection: 1 horizontal, 0 vertical (the seed's specialisation constant).
uniform sampler2D ImageUnit;
uniform int blurdirection;
uniform float uBlurScale;       // ubo.blurScale
uniform float uBlurStrength;    // ubo.blurStrength

in vec2 vST;

void main( )
{
    float weight[5];
    weight[0] = 0.227027;
    weight[1] = 0.1945946;
    weight[2] = 0.1216216;
    weight[3] = 0.054054;
    weight[4] = 0.016216;

    vec2 tex_offset = 1. / vec2( textureSize( ImageUnit, 0 ) ) * uBlurScale;
    vec3 result = texture( ImageUnit, vST ).rgb * weight[0];
    for( int i = 1; i < 5; ++i )
    {
        if( blurdirection == 1 )
        {
            // Horizontal blur
            result += texture( ImageUnit, vST + vec2( tex_offset.x * float(i), 0. ) ).rgb * weight[i] * uBlurStrength;
            result += texture( ImageUnit, vST - vec2( tex_offset.x * float(i), 0. ) ).rgb * weight[i] * uBlurStrength;
        }
        else
        {
            // Vertical blur
            result += texture( ImageUnit, vST + vec2( 0., tex_offset.y * float(i) ) ).rgb * weight[i] * uBlurStrength;
            result += texture( ImageUnit, vST - vec2( 0., tex_offset.y * float(i) ) ).rgb * weight[i] * uBlurStrength;
        }
    }
    gl_FragColor = vec4( result, 1. );
}
