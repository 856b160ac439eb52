//! Creating, deleting and configuring a NURBS object: `gluNewNurbsRenderer`,
//! `gluDeleteNurbsRenderer`, `gluNurbsProperty`, `gluGetNurbsProperty`,
//! `gluLoadSamplingMatrices`, `gluNurbsCallback`, `gluNurbsCallbackData`, and the automatic
//! loading of the sampling matrices from GL (`glrenderer.cc`, spec 2.3).

use crate::gl::types::*;
use crate::gl::Gl;
use crate::glu::consts::*;
use crate::glu::model::callbacks::{NurbsCallback, UserData};
use crate::glu::model::object::{GLUnurbs, NurbsObject};
use crate::glu::model::props::SamplingMatrices;

impl Gl {
    /// The object behind a handle; `None` once deleted (GLU's calls then do nothing).
    pub(super) fn nurbs(&mut self, nobj: GLUnurbs) -> Option<&mut NurbsObject> {
        self.glu.nurbs.get_mut(nobj.0)
    }

    /// Runs `f` with the object taken out of the context, so that it may draw through `self`.
    pub(super) fn with_nurbs<R>(
        &mut self,
        nobj: GLUnurbs,
        f: impl FnOnce(&mut Gl, &mut NurbsObject) -> R,
    ) -> Option<R> {
        let mut obj = self.glu.nurbs.take(nobj.0)?;
        let r = f(self, &mut obj);
        self.glu.nurbs.put_back(nobj.0, obj);
        Some(r)
    }

    /// `gluNewNurbsRenderer`: a new NURBS object with GLU's default properties.
    pub fn glu_new_nurbs_renderer(&mut self) -> GLUnurbs {
        GLUnurbs(self.glu.nurbs.insert(NurbsObject::new()))
    }

    /// `gluDeleteNurbsRenderer`. Later calls with the handle do nothing.
    pub fn glu_delete_nurbs_renderer(&mut self, nobj: GLUnurbs) {
        self.glu.nurbs.remove(nobj.0);
    }

    /// `gluNurbsProperty`. An unknown property → `GLU_INVALID_ENUM`; a bad display mode or
    /// sampling method → `GLU_INVALID_VALUE` (through the error callback; nothing changes).
    pub fn glu_nurbs_property(&mut self, nobj: GLUnurbs, property: GLenum, value: GLfloat) {
        let Some(obj) = self.nurbs(nobj) else { return };
        match obj.props.set(property, value) {
            Ok(()) if obj.props.object_space() => obj.matrices = SamplingMatrices::IDENTITY,
            Ok(()) => {}
            Err(code) => obj.callbacks.error(code),
        }
    }

    /// `gluGetNurbsProperty`: writes the value into `value[0]`.
    pub fn glu_get_nurbs_property(&mut self, nobj: GLUnurbs, property: GLenum, value: &mut [GLfloat]) {
        let Some(obj) = self.nurbs(nobj) else { return };
        match (obj.props.get(property), value.first_mut()) {
            (Ok(v), Some(out)) => *out = v,
            (Ok(_), None) => obj.callbacks.error(GLU_INVALID_VALUE),
            (Err(code), _) => obj.callbacks.error(code),
        }
    }

    /// `gluLoadSamplingMatrices(nobj, model, perspective, view)`: used while
    /// `GLU_AUTO_LOAD_MATRIX` is false.
    pub fn glu_load_sampling_matrices(
        &mut self,
        nobj: GLUnurbs,
        model: &[GLfloat],
        perspective: &[GLfloat],
        view: &[GLint],
    ) {
        let Some(obj) = self.nurbs(nobj) else { return };
        match (model.get(..16), perspective.get(..16), view.get(..4)) {
            (Some(m), Some(p), Some(v)) => {
                obj.matrices = SamplingMatrices {
                    modelview: glam::Mat4::from_cols_slice(m),
                    projection: glam::Mat4::from_cols_slice(p),
                    viewport: [v[0], v[1], v[2], v[3]],
                };
            }
            _ => obj.callbacks.error(GLU_INVALID_VALUE),
        }
    }

    /// `gluNurbsCallback(nobj, which, fn)`; `None` removes the callback. An unknown `which`, or
    /// a callback of another kind than `which` names → `GLU_INVALID_ENUM`.
    pub fn glu_nurbs_callback(&mut self, nobj: GLUnurbs, which: GLenum, callback: Option<NurbsCallback>) {
        let Some(obj) = self.nurbs(nobj) else { return };
        if !obj.callbacks.set(which, callback) {
            obj.callbacks.error(GLU_INVALID_ENUM);
        }
    }

    /// `gluNurbsCallbackData`: the user data the `_DATA` callbacks receive.
    pub fn glu_nurbs_callback_data(&mut self, nobj: GLUnurbs, data: UserData) {
        if let Some(obj) = self.nurbs(nobj) {
            obj.callbacks.data = Some(data);
        }
    }

    /// Loads the sampling matrices from the GL state when `GLU_AUTO_LOAD_MATRIX` is on
    /// (GLU's `bgnrender`).
    pub(super) fn auto_load_matrices(&mut self, nobj: GLUnurbs) {
        let current = SamplingMatrices {
            modelview: self.modelview_matrix(),
            projection: self.projection_matrix(),
            viewport: self.viewport_box(),
        };
        if let Some(obj) = self.nurbs(nobj) {
            if obj.props.auto_load_matrix {
                obj.matrices = current;
            }
        }
    }
}
