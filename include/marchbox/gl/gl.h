// marchbox/gl/gl.h — the one way project code reaches OpenGL.
//
// GLEW loads every entry point past OpenGL 1.1 through glXGetProcAddressARB. The 1.1 functions
// it leaves to the linker; here they go through pointers too, loaded the same way, because the
// off-screen path loads OSMesa privately (dlopen, RTLD_LOCAL) and a linked libGL would send
// them to a window system that has no current context. marchbox_gl does not link libGL, so
// a 1.1 function missing here fails to link in gl_tests instead of drawing nothing.
#pragma once

#include <GL/glew.h>

#include <string>

namespace mb {

struct Gl11 {
    void(GLAPIENTRY* Clear)(GLbitfield);
    void(GLAPIENTRY* ClearColor)(GLfloat, GLfloat, GLfloat, GLfloat);
    void(GLAPIENTRY* Viewport)(GLint, GLint, GLsizei, GLsizei);
    void(GLAPIENTRY* Scissor)(GLint, GLint, GLsizei, GLsizei);
    void(GLAPIENTRY* Enable)(GLenum);
    void(GLAPIENTRY* Disable)(GLenum);
    void(GLAPIENTRY* DrawElements)(GLenum, GLsizei, GLenum, const void*);
    void(GLAPIENTRY* ReadPixels)(GLint, GLint, GLsizei, GLsizei, GLenum, GLenum, void*);
    void(GLAPIENTRY* PixelStorei)(GLenum, GLint);
    void(GLAPIENTRY* GetIntegerv)(GLenum, GLint*);
    const GLubyte*(GLAPIENTRY* GetString)(GLenum);
    GLenum(GLAPIENTRY* GetError)();
    void(GLAPIENTRY* Finish)();
    void(GLAPIENTRY* GenTextures)(GLsizei, GLuint*);
    void(GLAPIENTRY* DeleteTextures)(GLsizei, const GLuint*);
    void(GLAPIENTRY* BindTexture)(GLenum, GLuint);
    void(GLAPIENTRY* TexImage2D)(GLenum, GLint, GLint, GLsizei, GLsizei, GLint, GLenum, GLenum,
                                 const void*);
    void(GLAPIENTRY* TexParameteri)(GLenum, GLenum, GLint);
    void(GLAPIENTRY* DrawArrays)(GLenum, GLint, GLsizei);
    void(GLAPIENTRY* BlendFunc)(GLenum, GLenum);
};
extern Gl11 gl11;

// Loads GLEW and the 1.1 table for the context current on this thread. `offscreen` accepts
// GLEW's "GLX 1.2 and up are not supported": OSMesa has no GLX, yet every function loaded.
bool loadGl(bool offscreen, std::string* error);

}  // namespace mb

#define glClear mb::gl11.Clear
#define glClearColor mb::gl11.ClearColor
#define glViewport mb::gl11.Viewport
#define glScissor mb::gl11.Scissor
#define glEnable mb::gl11.Enable
#define glDisable mb::gl11.Disable
#define glDrawElements mb::gl11.DrawElements
#define glReadPixels mb::gl11.ReadPixels
#define glPixelStorei mb::gl11.PixelStorei
#define glGetIntegerv mb::gl11.GetIntegerv
#define glGetString mb::gl11.GetString
#define glGetError mb::gl11.GetError
#define glFinish mb::gl11.Finish
#define glGenTextures mb::gl11.GenTextures
#define glDeleteTextures mb::gl11.DeleteTextures
#define glBindTexture mb::gl11.BindTexture
#define glTexImage2D mb::gl11.TexImage2D
#define glTexParameteri mb::gl11.TexParameteri
#define glDrawArrays mb::gl11.DrawArrays
#define glBlendFunc mb::gl11.BlendFunc
