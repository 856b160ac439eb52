/* GL/glew.h for gleval: what the GLEW of 2010s textbooks is used for, answered by gleval itself.
 *
 * A program written for GLEW calls `glewExperimental = GL_TRUE; glewInit();` after making its
 * window and then calls GL. Here glewInit succeeds (GLEW_OK) once a gleval context is current
 * (after glutCreateWindow), and the GL entry points are gleval's own, declared by <GL/gl.h>:
 * every function gleval has is callable directly, none is a null pointer. GLEW_VERSION_1_1 is
 * true; later versions and extensions answer as gleval's glGetString does (GL 1.1, no
 * extensions). Build with capi/glevalcc, which drops -lGLEW as it drops -lGL. */
#ifndef __glew_h__
#define __glew_h__
#define __GLEW_H__
#include <GL/gl.h>
#include <GL/glu.h>

#ifdef __cplusplus
extern "C" {
#endif

#define GLEW_OK 0
#define GLEW_NO_ERROR 0
#define GLEW_ERROR_NO_GL_VERSION 1
#define GLEW_ERROR_GL_VERSION_10_ONLY 2
#define GLEW_ERROR_GLX_VERSION_11_ONLY 3
#define GLEW_ERROR_NO_GLX_DISPLAY 4
#define GLEW_VERSION 1
#define GLEW_VERSION_MAJOR 2
#define GLEW_VERSION_MINOR 3
#define GLEW_VERSION_MICRO 4

/* Set before glewInit by programs for core profiles; kept, and changes nothing here. */
extern GLboolean glewExperimental;

GLenum glewInit(void);
GLboolean glewIsSupported(const char *name);
GLboolean glewGetExtension(const char *name);
const GLubyte *glewGetErrorString(GLenum error);
const GLubyte *glewGetString(GLenum name);

#define glewIsExtensionSupported(x) glewIsSupported(x)
#define GLEW_VERSION_1_1 glewIsSupported("GL_VERSION_1_1")
#define GLEW_VERSION_1_2 glewIsSupported("GL_VERSION_1_2")
#define GLEW_VERSION_1_3 glewIsSupported("GL_VERSION_1_3")
#define GLEW_VERSION_1_4 glewIsSupported("GL_VERSION_1_4")
#define GLEW_VERSION_1_5 glewIsSupported("GL_VERSION_1_5")
#define GLEW_VERSION_2_0 glewIsSupported("GL_VERSION_2_0")
#define GLEW_VERSION_2_1 glewIsSupported("GL_VERSION_2_1")
#define GLEW_VERSION_3_0 glewIsSupported("GL_VERSION_3_0")

/* The extensions of the GL 1.2-1.5 era by GLEW's flag names: each true exactly when gleval's
 * GL_EXTENSIONS lists it (the entry points of a listed one are gleval's own, never NULL). */
#define GLEW_ARB_multitexture glewIsSupported("GL_ARB_multitexture")
#define GLEW_ARB_transpose_matrix glewIsSupported("GL_ARB_transpose_matrix")
#define GLEW_ARB_multisample glewIsSupported("GL_ARB_multisample")
#define GLEW_ARB_texture_env_add glewIsSupported("GL_ARB_texture_env_add")
#define GLEW_ARB_texture_cube_map glewIsSupported("GL_ARB_texture_cube_map")
#define GLEW_ARB_texture_compression glewIsSupported("GL_ARB_texture_compression")
#define GLEW_ARB_texture_border_clamp glewIsSupported("GL_ARB_texture_border_clamp")
#define GLEW_ARB_point_parameters glewIsSupported("GL_ARB_point_parameters")
#define GLEW_ARB_texture_env_combine glewIsSupported("GL_ARB_texture_env_combine")
#define GLEW_ARB_texture_env_crossbar glewIsSupported("GL_ARB_texture_env_crossbar")
#define GLEW_ARB_texture_env_dot3 glewIsSupported("GL_ARB_texture_env_dot3")
#define GLEW_ARB_texture_mirrored_repeat glewIsSupported("GL_ARB_texture_mirrored_repeat")
#define GLEW_ARB_depth_texture glewIsSupported("GL_ARB_depth_texture")
#define GLEW_ARB_shadow glewIsSupported("GL_ARB_shadow")
#define GLEW_ARB_shadow_ambient glewIsSupported("GL_ARB_shadow_ambient")
#define GLEW_ARB_window_pos glewIsSupported("GL_ARB_window_pos")
#define GLEW_ARB_vertex_buffer_object glewIsSupported("GL_ARB_vertex_buffer_object")
#define GLEW_ARB_occlusion_query glewIsSupported("GL_ARB_occlusion_query")
#define GLEW_ARB_point_sprite glewIsSupported("GL_ARB_point_sprite")
#define GLEW_ARB_texture_non_power_of_two glewIsSupported("GL_ARB_texture_non_power_of_two")
#define GLEW_ARB_imaging glewIsSupported("GL_ARB_imaging")
#define GLEW_EXT_abgr glewIsSupported("GL_EXT_abgr")
#define GLEW_EXT_bgra glewIsSupported("GL_EXT_bgra")
#define GLEW_EXT_blend_color glewIsSupported("GL_EXT_blend_color")
#define GLEW_EXT_blend_equation_separate glewIsSupported("GL_EXT_blend_equation_separate")
#define GLEW_EXT_blend_func_separate glewIsSupported("GL_EXT_blend_func_separate")
#define GLEW_EXT_blend_minmax glewIsSupported("GL_EXT_blend_minmax")
#define GLEW_EXT_blend_subtract glewIsSupported("GL_EXT_blend_subtract")
#define GLEW_EXT_draw_range_elements glewIsSupported("GL_EXT_draw_range_elements")
#define GLEW_EXT_fog_coord glewIsSupported("GL_EXT_fog_coord")
#define GLEW_EXT_multi_draw_arrays glewIsSupported("GL_EXT_multi_draw_arrays")
#define GLEW_EXT_packed_pixels glewIsSupported("GL_EXT_packed_pixels")
#define GLEW_EXT_point_parameters glewIsSupported("GL_EXT_point_parameters")
#define GLEW_EXT_rescale_normal glewIsSupported("GL_EXT_rescale_normal")
#define GLEW_EXT_secondary_color glewIsSupported("GL_EXT_secondary_color")
#define GLEW_EXT_separate_specular_color glewIsSupported("GL_EXT_separate_specular_color")
#define GLEW_EXT_shadow_funcs glewIsSupported("GL_EXT_shadow_funcs")
#define GLEW_EXT_stencil_wrap glewIsSupported("GL_EXT_stencil_wrap")
#define GLEW_EXT_texture3D glewIsSupported("GL_EXT_texture3D")
#define GLEW_EXT_texture_compression_s3tc glewIsSupported("GL_EXT_texture_compression_s3tc")
#define GLEW_EXT_texture_cube_map glewIsSupported("GL_EXT_texture_cube_map")
#define GLEW_EXT_texture_edge_clamp glewIsSupported("GL_EXT_texture_edge_clamp")
#define GLEW_EXT_texture_env_add glewIsSupported("GL_EXT_texture_env_add")
#define GLEW_EXT_texture_env_combine glewIsSupported("GL_EXT_texture_env_combine")
#define GLEW_EXT_texture_env_dot3 glewIsSupported("GL_EXT_texture_env_dot3")
#define GLEW_EXT_texture_filter_anisotropic glewIsSupported("GL_EXT_texture_filter_anisotropic")
#define GLEW_EXT_texture_lod_bias glewIsSupported("GL_EXT_texture_lod_bias")
#define GLEW_EXT_texture_object glewIsSupported("GL_EXT_texture_object")
#define GLEW_EXT_vertex_array glewIsSupported("GL_EXT_vertex_array")
#define GLEW_EXT_framebuffer_object glewIsSupported("GL_EXT_framebuffer_object")
#define GLEW_IBM_texture_mirrored_repeat glewIsSupported("GL_IBM_texture_mirrored_repeat")
#define GLEW_NV_blend_square glewIsSupported("GL_NV_blend_square")
#define GLEW_NV_texgen_reflection glewIsSupported("GL_NV_texgen_reflection")
#define GLEW_SGIS_generate_mipmap glewIsSupported("GL_SGIS_generate_mipmap")
#define GLEW_SGIS_texture_border_clamp glewIsSupported("GL_SGIS_texture_border_clamp")
#define GLEW_SGIS_texture_edge_clamp glewIsSupported("GL_SGIS_texture_edge_clamp")
#define GLEW_SGIS_texture_lod glewIsSupported("GL_SGIS_texture_lod")

#ifdef __cplusplus
}
#endif
#endif /* __glew_h__ */
