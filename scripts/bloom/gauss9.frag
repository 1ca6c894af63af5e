#version 330 compatibility

// The 9-tap Gaussian of LearnOpenGL's "Bloom" chapter: centre weight[0], then
// weight[i] at +-i whole texels along one axis. The published weights are used
// as they are; they sum to 0.9999994, not 1 (src/reference/blur_reference.h,
// learnOpenGLWeights).
uniform sampler2D ImageUnit;
uniform int uHorizontal;        // 1: along s, 0: along t

in vec2 vST;

const float weight[5] = float[]( 0.227027, 0.1945946, 0.1216216, 0.054054, 0.016216 );

void main( )
{
    vec2 tex_offset = 1. / vec2( textureSize( ImageUnit, 0 ) );   // one texel
    vec2 step = uHorizontal != 0 ? vec2( tex_offset.x, 0. ) : vec2( 0., tex_offset.y );
    vec3 result = texture( ImageUnit, vST ).rgb * weight[0];
    for( int i = 1; i < 5; ++i )
    {
        result += texture( ImageUnit, vST + float(i) * step ).rgb * weight[i];
        result += texture( ImageUnit, vST - float(i) * step ).rgb * weight[i];
    }
    gl_FragColor = vec4( result, 1. );
}
