#version 120
uniform sampler2D PatternUnit;
uniform float uShine;
varying vec3 vN;

void main()
{
    vec3 n = normalize(vN);
    float d = max(dot(n, normalize(vec3(1, 1, 1))), 0);   // ints where floats go: GLSL 1.20 converts
    float one = 1;
    vec3 pattern = texture2D(PatternUnit, gl_TexCoord[0].st).rgb;
    gl_FragColor = vec4(gl_Color.rgb * (.2 + .8 * d) * (.5 + .5 * pattern) + uShine * pow(d, 20), one);
}
