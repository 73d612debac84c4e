// Reading data by index from a float texture laid 1024 texels to a row (gl::Texture::data_rows):
// what a storage buffer does on desktop GL, which WebGL2 lacks.
// Included by the shaders that pull data: #include "common/data_texture.glsl".
const int DATA_TEXTURE_WIDTH = 1024;  // gl::Texture::kDataTextureWidth
vec4 data_texel(sampler2D data, int index) {
  return texelFetch(data, ivec2(index % DATA_TEXTURE_WIDTH, index / DATA_TEXTURE_WIDTH), 0);
}
