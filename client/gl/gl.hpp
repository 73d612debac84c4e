#pragma once
// The OpenGL entry points Inkwire uses: only what GL 3.3 core and WebGL2 (GLES 3.0) share (SPEC
// W5), loaded from whichever context is current (OSMesa, EGL, GLFW; WebGL2 in the browser).
//
// Why not call libGL's symbols directly: a binary that links both OSMesa and libGL/libOpenGL
// sends calls to whichever library the dynamic linker found first, silently drawing nothing
// in the other. Every call here goes through a pointer the active context handed us.
// The pointers live in namespace inkwire::gl so they never interpose on the libraries' own
// exported gl* symbols.
#include <GL/glcorearb.h>

#include "client/gl/loader.hpp"

#define INKWIRE_GL_FUNCTIONS(X)                                              \
  X(PFNGLGETERRORPROC, glGetError)                                           \
  X(PFNGLGETSTRINGPROC, glGetString)                                         \
  X(PFNGLGETINTEGERVPROC, glGetIntegerv)                                     \
  X(PFNGLGETFLOATVPROC, glGetFloatv)                                         \
  X(PFNGLVIEWPORTPROC, glViewport)                                           \
  X(PFNGLSCISSORPROC, glScissor)                                             \
  X(PFNGLCLEARPROC, glClear)                                                 \
  X(PFNGLCLEARCOLORPROC, glClearColor)                                       \
  X(PFNGLCLEARDEPTHFPROC, glClearDepthf)                                       \
  X(PFNGLCLEARSTENCILPROC, glClearStencil)                                   \
  X(PFNGLENABLEPROC, glEnable)                                               \
  X(PFNGLDISABLEPROC, glDisable)                                             \
  X(PFNGLISENABLEDPROC, glIsEnabled)                                         \
  X(PFNGLDEPTHFUNCPROC, glDepthFunc)                                         \
  X(PFNGLDEPTHMASKPROC, glDepthMask)                                         \
  X(PFNGLCOLORMASKPROC, glColorMask)                                         \
  X(PFNGLCULLFACEPROC, glCullFace)                                           \
  X(PFNGLFRONTFACEPROC, glFrontFace)                                         \
  X(PFNGLBLENDFUNCPROC, glBlendFunc)                                         \
  X(PFNGLBLENDFUNCSEPARATEPROC, glBlendFuncSeparate)                         \
  X(PFNGLPOLYGONOFFSETPROC, glPolygonOffset)                                 \
  X(PFNGLSTENCILFUNCPROC, glStencilFunc)                                     \
  X(PFNGLSTENCILOPPROC, glStencilOp)                                         \
  X(PFNGLSTENCILMASKPROC, glStencilMask)                                     \
  X(PFNGLFINISHPROC, glFinish)                                               \
  X(PFNGLFLUSHPROC, glFlush)                                                 \
  X(PFNGLREADPIXELSPROC, glReadPixels)                                       \
  X(PFNGLPIXELSTOREIPROC, glPixelStorei)                                     \
  X(PFNGLDRAWARRAYSPROC, glDrawArrays)                                       \
  X(PFNGLDRAWELEMENTSPROC, glDrawElements)                                   \
  X(PFNGLDRAWARRAYSINSTANCEDPROC, glDrawArraysInstanced) \
  X(PFNGLVERTEXATTRIBDIVISORPROC, glVertexAttribDivisor)                     \
  X(PFNGLGENBUFFERSPROC, glGenBuffers)                                       \
  X(PFNGLDELETEBUFFERSPROC, glDeleteBuffers)                                 \
  X(PFNGLBINDBUFFERPROC, glBindBuffer)                                       \
  X(PFNGLBUFFERDATAPROC, glBufferData)                                       \
  X(PFNGLBUFFERSUBDATAPROC, glBufferSubData)                                 \
  X(PFNGLGENVERTEXARRAYSPROC, glGenVertexArrays)                             \
  X(PFNGLDELETEVERTEXARRAYSPROC, glDeleteVertexArrays)                       \
  X(PFNGLBINDVERTEXARRAYPROC, glBindVertexArray)                             \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, glEnableVertexAttribArray)             \
  X(PFNGLVERTEXATTRIBPOINTERPROC, glVertexAttribPointer)                     \
  X(PFNGLVERTEXATTRIBIPOINTERPROC, glVertexAttribIPointer)                   \
  X(PFNGLGENTEXTURESPROC, glGenTextures)                                     \
  X(PFNGLDELETETEXTURESPROC, glDeleteTextures)                               \
  X(PFNGLBINDTEXTUREPROC, glBindTexture)                                     \
  X(PFNGLACTIVETEXTUREPROC, glActiveTexture)                                 \
  X(PFNGLTEXIMAGE2DPROC, glTexImage2D)                                       \
  X(PFNGLTEXIMAGE3DPROC, glTexImage3D)                                       \
  X(PFNGLTEXSUBIMAGE2DPROC, glTexSubImage2D)                                 \
  X(PFNGLTEXPARAMETERIPROC, glTexParameteri)                                 \
  X(PFNGLTEXPARAMETERFPROC, glTexParameterf)                                 \
  X(PFNGLGENERATEMIPMAPPROC, glGenerateMipmap)                               \
  X(PFNGLCREATESHADERPROC, glCreateShader)                                   \
  X(PFNGLSHADERSOURCEPROC, glShaderSource)                                   \
  X(PFNGLCOMPILESHADERPROC, glCompileShader)                                 \
  X(PFNGLGETSHADERIVPROC, glGetShaderiv)                                     \
  X(PFNGLGETSHADERINFOLOGPROC, glGetShaderInfoLog)                           \
  X(PFNGLDELETESHADERPROC, glDeleteShader)                                   \
  X(PFNGLCREATEPROGRAMPROC, glCreateProgram)                                 \
  X(PFNGLATTACHSHADERPROC, glAttachShader)                                   \
  X(PFNGLLINKPROGRAMPROC, glLinkProgram)                                     \
  X(PFNGLGETPROGRAMIVPROC, glGetProgramiv)                                   \
  X(PFNGLGETPROGRAMINFOLOGPROC, glGetProgramInfoLog)                         \
  X(PFNGLDELETEPROGRAMPROC, glDeleteProgram)                                 \
  X(PFNGLUSEPROGRAMPROC, glUseProgram)                                       \
  X(PFNGLGETUNIFORMLOCATIONPROC, glGetUniformLocation)                       \
  X(PFNGLUNIFORM1IPROC, glUniform1i)                                         \
  X(PFNGLUNIFORM1FPROC, glUniform1f)                                         \
  X(PFNGLUNIFORM2FPROC, glUniform2f)                                         \
  X(PFNGLUNIFORM3FPROC, glUniform3f)                                         \
  X(PFNGLUNIFORM3IPROC, glUniform3i)                                         \
  X(PFNGLUNIFORM4FPROC, glUniform4f)                                         \
  X(PFNGLUNIFORMMATRIX2FVPROC, glUniformMatrix2fv)                           \
  X(PFNGLUNIFORMMATRIX3FVPROC, glUniformMatrix3fv)                           \
  X(PFNGLUNIFORMMATRIX4FVPROC, glUniformMatrix4fv)                           \
  X(PFNGLGENFRAMEBUFFERSPROC, glGenFramebuffers)                             \
  X(PFNGLDELETEFRAMEBUFFERSPROC, glDeleteFramebuffers)                       \
  X(PFNGLBINDFRAMEBUFFERPROC, glBindFramebuffer)                             \
  X(PFNGLFRAMEBUFFERTEXTURE2DPROC, glFramebufferTexture2D)                   \
  X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, glFramebufferRenderbuffer)             \
  X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, glCheckFramebufferStatus)               \
  X(PFNGLGENRENDERBUFFERSPROC, glGenRenderbuffers)                           \
  X(PFNGLDELETERENDERBUFFERSPROC, glDeleteRenderbuffers)                     \
  X(PFNGLBINDRENDERBUFFERPROC, glBindRenderbuffer)                           \
  X(PFNGLRENDERBUFFERSTORAGEMULTISAMPLEPROC, glRenderbufferStorageMultisample) \
  X(PFNGLBLITFRAMEBUFFERPROC, glBlitFramebuffer)                             \
  X(PFNGLDRAWBUFFERSPROC, glDrawBuffers)                                     \
  X(PFNGLREADBUFFERPROC, glReadBuffer)                                       \
  X(PFNGLGENQUERIESPROC, glGenQueries)                                       \
  X(PFNGLDELETEQUERIESPROC, glDeleteQueries)                                 \
  X(PFNGLBEGINQUERYPROC, glBeginQuery)                                       \
  X(PFNGLENDQUERYPROC, glEndQuery)                                           \
  X(PFNGLGETQUERYOBJECTUIVPROC, glGetQueryObjectuiv)                         \
  X(PFNGLBINDBUFFERBASEPROC, glBindBufferBase)

namespace inkwire::gl {

#define INKWIRE_GL_DECLARE(type, name) extern type name;
INKWIRE_GL_FUNCTIONS(INKWIRE_GL_DECLARE)
#undef INKWIRE_GL_DECLARE

// Throws inkwire::Error "<where>: GL error 0x...." if the context recorded an error.
void check_error(const char* where);

}  // namespace inkwire::gl
