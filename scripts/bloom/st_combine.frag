#version 330 compatibility

// Sol Trader, step 4: the original plus the four blurred glow buffers, clamped.
uniform sampler2D uTextureOriginal;
uniform sampler2D uTexture1;
uniform sampler2D uTexture2;
uniform sampler2D uTexture3;
uniform sampler2D uTexture4;

in vec2 vST;

void main( )
{
    vec4 vOriginal = texture( uTextureOriginal, vST );
    vec4 vT1 = texture( uTexture1, vST );
    vec4 vT2 = texture( uTexture2, vST );
    vec4 vT3 = texture( uTexture3, vST );
    vec4 vT4 = texture( uTexture4, vST );
    gl_FragColor = vec4( clamp( vOriginal + vT1 + vT2 + vT3 + vT4, 0.0, 1.0 ).rgb, 1. );
}
