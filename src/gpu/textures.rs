//! GL's fragment operations on wgpu: each [`BoundTexture`] of a frame uploaded once per version
//! (its key), a sampler per GL filter and wrap combination, and the texture environment, fog
//! and alpha test as a uniform (`shaders/raster.wgsl` applies them per fragment; blending is
//! the pipeline's).

use super::layout::GpuFragment;
use crate::gl::consts::*;
use crate::gl::types::GLenum;
use crate::gl::{BoundTexture, Combiner, TexParams};
use crate::render::assemble::{FragmentState, Smooth};
use std::collections::HashMap;
use wgpu::util::DeviceExt;

impl GpuFragment {
    fn of(fragment: &FragmentState, height: u32) -> Self {
        let mut out = Self { height, ..Self::default() };
        if let Some(rows) = fragment.polygon_stipple {
            out.stipple = 1;
            out.stipple_rows = std::array::from_fn(|k| std::array::from_fn(|i| rows[4 * k + i]));
        }
        if let Some(texture) = &fragment.texture {
            out.set_texture(texture);
        }
        if let Some(fog) = &fragment.fog {
            out.fog_mode = match fog.mode {
                GL_LINEAR => 1,
                GL_EXP => 2,
                _ => 3,
            };
            (out.fog_density, out.fog_start, out.fog_end, out.fog_color) = (fog.density, fog.start, fog.end, fog.color);
        }
        if let Some((func, reference)) = fragment.alpha_test {
            (out.alpha_func, out.alpha_ref) = (func - GL_NEVER + 1, reference);
        }
        out.coverage = match fragment.smooth {
            Smooth::None => 0,
            Smooth::Point => 1,
            Smooth::Line => 2,
        };
        out
    }

    fn set_texture(&mut self, texture: &BoundTexture) {
        self.mode = match texture.env_mode {
            GL_MODULATE => 1,
            GL_DECAL => 2,
            GL_BLEND => 3,
            GL_REPLACE => 4,
            GL_ADD => 5,
            _ => 6,
        };
        self.combine_rgb = combiner_uniform(&texture.combine.rgb);
        self.combine_alpha = combiner_uniform(&texture.combine.alpha);
        self.format = match texture.base_format {
            GL_ALPHA => 0,
            GL_LUMINANCE => 1,
            GL_LUMINANCE_ALPHA => 2,
            GL_RGB => 3,
            GL_INTENSITY => 5,
            _ => 4,
        };
        let linear = texture.params.mag_filter == GL_LINEAR
            && matches!(texture.params.min_filter, GL_LINEAR | GL_LINEAR_MIPMAP_NEAREST | GL_LINEAR_MIPMAP_LINEAR);
        let clamp = |w: GLenum| match (w, linear) {
            (GL_CLAMP, false) => 1,
            (GL_CLAMP, true) => 2,
            (GL_CLAMP_TO_BORDER, false) => 3,
            (GL_CLAMP_TO_BORDER, true) => 4,
            _ => 0,
        };
        let clamp_t = if texture.dims == 1 { 0 } else { clamp(texture.params.wrap_t) };
        let clamp_r = if texture.dims == 3 { clamp(texture.params.wrap_r) } else { 0 };
        (self.clamp_s, self.clamp_t, self.clamp_r) = (clamp(texture.params.wrap_s), clamp_t, clamp_r);
        self.dims = u32::from(texture.dims.max(2));
        self.color = texture.env_color;
        self.border_color = texture.border_color;
    }
}

/// A combiner half as `fragment.wgsl`'s `Fragment` packs it: function, sources, operands (four
/// bits each) and scale.
fn combiner_uniform(half: &Combiner) -> [u32; 4] {
    let function = match half.function {
        GL_REPLACE => 1,
        GL_MODULATE => 2,
        GL_ADD => 3,
        GL_ADD_SIGNED => 4,
        GL_INTERPOLATE => 5,
        GL_SUBTRACT => 6,
        GL_DOT3_RGB => 7,
        _ => 8,
    };
    let source = |s: GLenum| match s {
        GL_TEXTURE | GL_TEXTURE0 => 0,
        GL_CONSTANT => 1,
        GL_PRIMARY_COLOR | GL_PREVIOUS => 2,
        _ => 3,
    };
    let operand = |o: GLenum| match o {
        GL_SRC_COLOR => 0,
        GL_ONE_MINUS_SRC_COLOR => 1,
        GL_SRC_ALPHA => 2,
        _ => 3,
    };
    let packed = |f: &dyn Fn(GLenum) -> u32, values: [GLenum; 3]| {
        values.iter().enumerate().fold(0, |bits, (k, &v)| bits | f(v) << (4 * k))
    };
    [function, packed(&source, half.sources), packed(&operand, half.operands), u32::from(half.scale)]
}

/// The bind group layout of `raster.wgsl`'s group 0: the 1D or 2D image, sampler, environment,
/// the 3D image.
pub(crate) fn bind_group_layout(device: &wgpu::Device) -> wgpu::BindGroupLayout {
    let fragment = wgpu::ShaderStages::FRAGMENT;
    let image = |binding, view_dimension| wgpu::BindGroupLayoutEntry {
        binding,
        visibility: fragment,
        ty: wgpu::BindingType::Texture {
            sample_type: wgpu::TextureSampleType::Float { filterable: true },
            view_dimension,
            multisampled: false,
        },
        count: None,
    };
    device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("texture"),
        entries: &[
            image(0, wgpu::TextureViewDimension::D2),
            wgpu::BindGroupLayoutEntry {
                binding: 1,
                visibility: fragment,
                ty: wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Filtering),
                count: None,
            },
            super::device::uniform(2, fragment, false),
            image(3, wgpu::TextureViewDimension::D3),
        ],
    })
}

/// Uploaded textures and samplers, kept between frames.
#[derive(Default)]
pub(crate) struct TextureCache {
    views: HashMap<u64, wgpu::TextureView>,
    /// The blank 3D image bound beside a 1D or 2D texture (and the blank 2D one, under key 0 in
    /// `views`, beside a 3D texture).
    blank_3d: Option<wgpu::TextureView>,
    samplers: HashMap<(TexParams, u8), wgpu::Sampler>,
}

impl TextureCache {
    /// One bind group per fragment state of the frame (in the order of `fragments`), then one
    /// for batches without any, for a target `height` pixels tall (the polygon stipple's rows
    /// count from its bottom). Textures of earlier frames not drawn now are dropped.
    pub(crate) fn bind_groups(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        layout: &wgpu::BindGroupLayout,
        fragments: &[FragmentState],
        height: u32,
    ) -> Vec<wgpu::BindGroup> {
        let drawn = |key: u64| key == 0 || fragments.iter().any(|f| f.texture.as_ref().is_some_and(|t| t.key == key));
        self.views.retain(|key, _| drawn(*key));
        let blank = BoundTexture::blank();
        let blank_2d = self.views.entry(0).or_insert_with(|| upload(device, queue, &blank)).clone();
        let blank_3d = self.blank_3d.get_or_insert_with(|| upload(device, queue, &blank_3d())).clone();
        let mut groups = Vec::with_capacity(fragments.len() + 1);
        for fragment in fragments.iter().map(Some).chain([None]) {
            let t = fragment.and_then(|f| f.texture.as_ref()).unwrap_or(&blank);
            let view = self.views.entry(t.key).or_insert_with(|| upload(device, queue, t)).clone();
            let images = if t.dims == 3 { (&blank_2d, &view) } else { (&view, &blank_3d) };
            let key = (t.params, t.dims);
            let sampler = self.samplers.entry(key).or_insert_with(|| sampler(device, &t.params, t.dims));
            let uniform = fragment.map(|f| GpuFragment::of(f, height)).unwrap_or_default();
            groups.push(bind_group(device, layout, images, sampler, uniform));
        }
        groups
    }
}

/// A 1×1×1 white 3D texture, for where no 3D texture is drawn.
fn blank_3d() -> BoundTexture {
    BoundTexture { dims: 3, ..BoundTexture::blank() }
}

fn bind_group(
    device: &wgpu::Device,
    layout: &wgpu::BindGroupLayout,
    (flat, solid): (&wgpu::TextureView, &wgpu::TextureView),
    sampler: &wgpu::Sampler,
    fragment: GpuFragment,
) -> wgpu::BindGroup {
    let uniform = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: Some("fragment"),
        contents: bytemuck::bytes_of(&fragment),
        usage: wgpu::BufferUsages::UNIFORM,
    });
    device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some("texture"),
        layout,
        entries: &[
            wgpu::BindGroupEntry { binding: 0, resource: wgpu::BindingResource::TextureView(flat) },
            wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::Sampler(sampler) },
            wgpu::BindGroupEntry { binding: 2, resource: uniform.as_entire_binding() },
            wgpu::BindGroupEntry { binding: 3, resource: wgpu::BindingResource::TextureView(solid) },
        ],
    })
}

/// The texture's levels as an RGBA8 wgpu texture (3D for a 3D texture); GL's first row (t = 0)
/// is row 0, its first image (r = 0) image 0.
fn upload(device: &wgpu::Device, queue: &wgpu::Queue, texture: &BoundTexture) -> wgpu::TextureView {
    let base = &texture.levels[0];
    let size = wgpu::Extent3d { width: base.width, height: base.height, depth_or_array_layers: base.depth };
    let dimension = if texture.dims == 3 { wgpu::TextureDimension::D3 } else { wgpu::TextureDimension::D2 };
    let gpu = device.create_texture(&wgpu::TextureDescriptor {
        label: Some("gl texture"),
        size,
        mip_level_count: texture.levels.len() as u32,
        sample_count: 1,
        dimension,
        format: wgpu::TextureFormat::Rgba8Unorm,
        usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
        view_formats: &[],
    });
    for (mip, level) in texture.levels.iter().enumerate() {
        queue.write_texture(
            wgpu::TexelCopyTextureInfo {
                texture: &gpu,
                mip_level: mip as u32,
                origin: wgpu::Origin3d::ZERO,
                aspect: wgpu::TextureAspect::All,
            },
            bytemuck::cast_slice(&level.texels),
            wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(4 * level.width),
                rows_per_image: Some(level.height),
            },
            wgpu::Extent3d { width: level.width, height: level.height, depth_or_array_layers: level.depth },
        );
    }
    gpu.create_view(&Default::default())
}

/// GL's filters and wrap modes as a wgpu sampler (GL 1.1 §3.8.5–3.8.8). `GL_CLAMP` and
/// `GL_CLAMP_TO_BORDER` clamp to the edge here; the shader clamps the coordinate (`GL_CLAMP`)
/// and mixes in the border colour, the same on every backend (WebGPU has no border colour). A 1D texture ignores t; r is wrapped for a 3D texture only.
fn sampler(device: &wgpu::Device, params: &TexParams, dims: u8) -> wgpu::Sampler {
    let filter = |f: GLenum| if f == GL_NEAREST { wgpu::FilterMode::Nearest } else { wgpu::FilterMode::Linear };
    let (min, mip) = match params.min_filter {
        GL_NEAREST => (wgpu::FilterMode::Nearest, None),
        GL_LINEAR => (wgpu::FilterMode::Linear, None),
        GL_NEAREST_MIPMAP_NEAREST => (wgpu::FilterMode::Nearest, Some(wgpu::MipmapFilterMode::Nearest)),
        GL_LINEAR_MIPMAP_NEAREST => (wgpu::FilterMode::Linear, Some(wgpu::MipmapFilterMode::Nearest)),
        GL_NEAREST_MIPMAP_LINEAR => (wgpu::FilterMode::Nearest, Some(wgpu::MipmapFilterMode::Linear)),
        _ => (wgpu::FilterMode::Linear, Some(wgpu::MipmapFilterMode::Linear)),
    };
    // A NaN bound clamps nothing, as on the CPU (`LodRange::clamp`); WebGPU takes no NaN.
    let lod_min = if params.lod.min.is_nan() { 0.0 } else { params.lod.min.clamp(0.0, 32.0) };
    let lod_max = if params.lod.max.is_nan() { 32.0 } else { params.lod.max.clamp(lod_min, 32.0) };
    let wrap = |w: GLenum| match w {
        GL_REPEAT => wgpu::AddressMode::Repeat,
        GL_MIRRORED_REPEAT => wgpu::AddressMode::MirrorRepeat,
        _ => wgpu::AddressMode::ClampToEdge,
    };
    let v = if dims == 1 { wgpu::AddressMode::Repeat } else { wrap(params.wrap_t) };
    let w = if dims == 3 { wrap(params.wrap_r) } else { wgpu::AddressMode::Repeat };
    device.create_sampler(&wgpu::SamplerDescriptor {
        label: Some("gl sampler"),
        address_mode_u: wrap(params.wrap_s),
        address_mode_v: v,
        address_mode_w: w,
        mag_filter: filter(params.mag_filter),
        min_filter: min,
        mipmap_filter: mip.unwrap_or(wgpu::MipmapFilterMode::Nearest),
        // GL 1.2's LOD clamp, which also decides between magnification and minification, as
        // Vulkan's does. WebGPU takes no negative bound: below 0 both magnify alike. Without a
        // mipmap filter the chain has one level, so only the choice of filter is left to it.
        lod_min_clamp: lod_min,
        lod_max_clamp: lod_max,
        ..Default::default()
    })
}
