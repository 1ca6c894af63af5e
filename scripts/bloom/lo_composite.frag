#version 330 compatibility

// LearnOpenGL "Bloom", the final pass: the blurred bright image added to the HDR
// scene BEFORE tone mapping, then exposure tone mapping 1 - exp(-c * exposure)
// and gamma correction (the chapter fixes gamma at 2.2; here it is a slider).
uniform sampler2D SceneUnit;
uniform sampler2D BloomUnit;
uniform float uExposure;
uniform float uGamma;

in vec2 vST;

void main( )
{
    vec3 hdrColor = texture( SceneUnit, vST ).rgb;
    vec3 bloomColor = texture( BloomUnit, vST ).rgb;
    hdrColor += bloomColor;                                   // additive blending
    vec3 result = vec3( 1. ) - exp( -hdrColor * uExposure );  // tone mapping
    result = pow( result, vec3( 1. / uGamma ) );              // gamma correction
    gl_FragColor = vec4( result, 1. );
}
