//! # cg-gpu — the kit's GPU renderer on wgpu
//!
//! Draws a [`cg_core::scene::Scene`] on the GPU as the CPU rasterizer (`cg-raster`) draws it:
//! flat, Gouraud and Phong shading (フラット／グロー／フォンシェーディング), the lecture's light model
//! and the OpenGL-compatible one, directional, point, spot and area lights, textures (nearest /
//! bilinear, repeat / clamp, modulate / replace), a depth test (GL_LESS), back-face culling and
//! the scene's perspective projection.
//!
//! **Only what the scene needs.** The WGSL is one file a TA reads, `src/shader.wgsl`, from
//! which [`shader_source`] keeps the parts [`Scene::features`](cg_core::scene::Scene::features)
//! need: a scene without specular, spot lights or textures gets a shader with no code for them;
//! [`enabled`] names what a shader contains.
//!
//! **Preparation apart from the device.** `prepare.rs` turns a scene into what the GPU draws
//! (the expanded vertices, the uniforms, the lights) on the CPU alone, tested without a GPU;
//! [`Gpu::frame`] only uploads it.
//!
//! ```no_run
//! use cg_gpu::{Gpu, Options};
//! let scene = cg_scene::load(std::path::Path::new("assets/scenes/course-sample.toml")).unwrap();
//! let gpu = Gpu::new().unwrap(); // GpuError::NoAdapter without a Vulkan driver
//! println!("{}", gpu.adapter_info());
//! let out = gpu.render(&scene, &Options::default()).unwrap();
//! assert_eq!(out.image.width, 640);
//! ```
//!
//! ## How it matches the CPU rasterizer
//!
//! The CPU prepares the geometry exactly as the rasterizer does ([`cg_core::scene::Object::prepare`]):
//! world positions by the model matrix, world normals by the cofactor matrix (flipped back for
//! mirrored objects, whose faces are also re-wound), face normals from the world corners, texture
//! coordinates shifted by the face's repeat origin. Faces are expanded to three vertices each, so
//! a face can carry its own face normal and, for flat shading, the point, normal and colour it is
//! lit with (the lecture's model: its centroid, face normal and average colour; OpenGL's: its
//! provoking vertex's, as GL_FLAT). The GPU transforms by
//! `projection · view`, lights in world space ([`shader`] says where for each shading mode),
//! clamps where the rasterizer clamps, and writes an `Rgba8Unorm` target read back into an
//! [`Image`] (row 0 at the top, as the rasterizer's). An area light is its
//! [`cg_core::light::Light::point_lights`] samples, as on the CPU.
//!
//! Differences: lighting is in f32 on the GPU (the CPU computes some cosines in f64), the
//! GPU's rasterization rules and bilinear weights are the driver's, and the GPU clips at the
//! near and far planes (the rasterizer clips the same planes). The tests measure the agreement.
//!
//! ## For a window
//!
//! [`Gpu::frame`] makes a [`Frame`] (buffers, bind groups, the pipeline) for a colour format, and
//! [`Gpu::render_to_view`] draws it into any texture view of that format and size — a surface's
//! current texture. Use a non-sRGB format (`Bgra8Unorm` / `Rgba8Unorm`): the kit's colours are
//! written as they are, as OpenGL 1.x did. [`Gpu::instance`], [`Gpu::adapter`],
//! [`Gpu::device`] and [`Gpu::queue`] give the wgpu objects a surface needs.

mod error;
mod prepare;
mod readback;
pub mod shader;

use std::collections::HashMap;
use std::sync::Mutex;

use cg_core::features::Features;
use cg_core::image::{Image, check_size};
use cg_core::scene::{Scene, Shading};
use cg_core::texture::{Filter, Wrap};
use wgpu::util::DeviceExt;

use prepare::{FrameUniform, GpuLight, GpuVertex, Prepared, frame_uniform, prepare};

pub use error::GpuError;
pub use shader::{enabled, shader_source};
/// The wgpu this crate is built with, for callers that make surfaces and views.
pub use wgpu;

/// What to draw besides the scene: like the rasterizer's options.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Options {
    /// Overrides the scene's shading mode.
    pub shading: Option<Shading>,
    /// Overrides the scene's image size `(width, height)`; the projection keeps its fovy and
    /// takes this aspect ratio.
    pub size: Option<(u32, u32)>,
}

/// What [`Gpu::render`] gives back.
#[derive(Clone, Debug, PartialEq)]
pub struct Output {
    /// The image, row 0 at the top (as the rasterizer's).
    pub image: Image,
    /// What the scene uses (reflection and transmission cleared: they need rays).
    pub features: Features,
    /// The shading mode drawn.
    pub shading: Shading,
    /// What the generated shader contains ([`enabled`]).
    pub enabled: Vec<cg_core::lang::Text>,
    /// The generated WGSL.
    pub shader: String,
}

/// One GPU device and queue, created once ([`Gpu::new`]) and used for every render. Pipelines
/// are compiled once per generated shader and kept.
pub struct Gpu {
    instance: wgpu::Instance,
    adapter: wgpu::Adapter,
    device: wgpu::Device,
    queue: wgpu::Queue,
    frame_layout: wgpu::BindGroupLayout,
    object_layout: wgpu::BindGroupLayout,
    object_layout_textured: wgpu::BindGroupLayout,
    pipelines: Mutex<HashMap<PipelineKey, wgpu::RenderPipeline>>,
}

impl std::fmt::Debug for Gpu {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Gpu").field("adapter", &self.adapter_info()).finish_non_exhaustive()
    }
}

#[derive(Clone, Debug, PartialEq, Eq, Hash)]
struct PipelineKey {
    shader: String,
    cull: bool,
    textured: bool,
    format: wgpu::TextureFormat,
}

/// The depth buffer's format.
const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;
/// The format [`Gpu::render`] draws and reads back.
pub const READBACK_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8Unorm;

/// One object ready to draw: its vertices and its bind group.
#[derive(Debug)]
struct DrawCall {
    vertices: wgpu::Buffer,
    count: u32,
    bind_group: wgpu::BindGroup,
}

/// A scene made ready to draw at one size into one colour format: the generated shader, its
/// pipeline, the buffers and bind groups, the depth buffer. Draw it with
/// [`Gpu::render_to_view`] as often as needed (a window redraws it every frame).
#[derive(Debug)]
pub struct Frame {
    /// Width of the target in pixels.
    pub width: u32,
    /// Height of the target in pixels.
    pub height: u32,
    /// The colour format it draws into.
    pub format: wgpu::TextureFormat,
    /// The shading mode.
    pub shading: Shading,
    /// What the scene uses (reflection and transmission cleared).
    pub features: Features,
    /// The generated WGSL.
    pub shader: String,
    clear: wgpu::Color,
    pipeline: wgpu::RenderPipeline,
    frame_bind_group: wgpu::BindGroup,
    frame_buffer: wgpu::Buffer,
    light_count: u32,
    draws: Vec<DrawCall>,
    depth: wgpu::TextureView,
    /// The read-back target and buffer, made on the first [`Gpu::read_back_into`].
    readback: Mutex<Option<readback::Readback>>,
}

impl Gpu {
    /// Opens the first adapter wgpu offers (a real GPU, or Mesa's lavapipe) and one device.
    ///
    /// # Errors
    /// [`GpuError::NoAdapter`] when there is none; [`GpuError::Device`] when it refuses a device.
    pub fn new() -> Result<Gpu, GpuError> {
        let instance =
            wgpu::Instance::new(wgpu::InstanceDescriptor::new_without_display_handle_from_env());
        let adapter = pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions {
            power_preference: wgpu::PowerPreference::HighPerformance,
            ..wgpu::RequestAdapterOptions::default()
        }))
        .map_err(|_| GpuError::NoAdapter)?;
        let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
            label: Some("cg-gpu"),
            // The adapter's largest buffer (wgpu's default is 256 MiB: 1.3 M triangles' vertices).
            required_limits: wgpu::Limits {
                max_buffer_size: adapter.limits().max_buffer_size,
                ..wgpu::Limits::downlevel_defaults().using_resolution(adapter.limits())
            },
            ..wgpu::DeviceDescriptor::default()
        }))
        .map_err(|e| GpuError::Device(e.to_string()))?;
        let both = wgpu::ShaderStages::VERTEX_FRAGMENT;
        let frame_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("cg-gpu frame"),
            entries: &[
                wgpu::BindGroupLayoutEntry {
                    binding: 0,
                    visibility: both,
                    ty: wgpu::BindingType::Buffer {
                        ty: wgpu::BufferBindingType::Uniform,
                        has_dynamic_offset: false,
                        min_binding_size: None,
                    },
                    count: None,
                },
                wgpu::BindGroupLayoutEntry {
                    binding: 1,
                    visibility: both,
                    ty: wgpu::BindingType::Buffer {
                        ty: wgpu::BufferBindingType::Storage { read_only: true },
                        has_dynamic_offset: false,
                        min_binding_size: None,
                    },
                    count: None,
                },
            ],
        });
        let object_uniform = wgpu::BindGroupLayoutEntry {
            binding: 0,
            visibility: both,
            ty: wgpu::BindingType::Buffer {
                ty: wgpu::BufferBindingType::Uniform,
                has_dynamic_offset: false,
                min_binding_size: None,
            },
            count: None,
        };
        let object_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("cg-gpu object"),
            entries: &[object_uniform],
        });
        let object_layout_textured =
            device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
                label: Some("cg-gpu textured object"),
                entries: &[
                    object_uniform,
                    wgpu::BindGroupLayoutEntry {
                        binding: 1,
                        visibility: wgpu::ShaderStages::FRAGMENT,
                        ty: wgpu::BindingType::Texture {
                            sample_type: wgpu::TextureSampleType::Float { filterable: true },
                            view_dimension: wgpu::TextureViewDimension::D2,
                            multisampled: false,
                        },
                        count: None,
                    },
                    wgpu::BindGroupLayoutEntry {
                        binding: 2,
                        visibility: wgpu::ShaderStages::FRAGMENT,
                        ty: wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Filtering),
                        count: None,
                    },
                ],
            });
        Ok(Gpu {
            instance,
            adapter,
            device,
            queue,
            frame_layout,
            object_layout,
            object_layout_textured,
            pipelines: Mutex::new(HashMap::new()),
        })
    }

    /// The adapter in one line: name, backend, device type, driver.
    #[must_use]
    pub fn adapter_info(&self) -> String {
        let i = self.adapter.get_info();
        format!(
            "{} ({:?}, {:?}, driver {} {})",
            i.name, i.backend, i.device_type, i.driver, i.driver_info
        )
    }

    /// The wgpu instance (a window makes its surface from it).
    #[must_use]
    pub fn instance(&self) -> &wgpu::Instance {
        &self.instance
    }

    /// The adapter in use.
    #[must_use]
    pub fn adapter(&self) -> &wgpu::Adapter {
        &self.adapter
    }

    /// The device.
    #[must_use]
    pub fn device(&self) -> &wgpu::Device {
        &self.device
    }

    /// The queue.
    #[must_use]
    pub fn queue(&self) -> &wgpu::Queue {
        &self.queue
    }

    /// Renders `scene` headless into an `Rgba8Unorm` texture and reads it back.
    ///
    /// # Errors
    /// A [`GpuError`] for a zero or too large size, an invalid camera or projection, an object
    /// that cannot be prepared, a missing texture, a non-finite vertex, or an error wgpu reports.
    pub fn render(&self, scene: &Scene, options: &Options) -> Result<Output, GpuError> {
        let frame = self.frame(scene, options, READBACK_FORMAT)?;
        let image = self.read_back(&frame)?;
        Ok(Output {
            image,
            features: frame.features,
            shading: frame.shading,
            enabled: enabled(&frame.features),
            shader: frame.shader,
        })
    }

    /// Draws `frame` into `view` (a texture view of `frame.format`, `frame.width ×
    /// frame.height` pixels, usable as a render attachment): clear, draw every object, submit.
    pub fn render_to_view(&self, frame: &Frame, view: &wgpu::TextureView) {
        let mut encoder = self
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("cg-gpu draw") });
        {
            let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("cg-gpu scene"),
                color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                    view,
                    depth_slice: None,
                    resolve_target: None,
                    ops: wgpu::Operations {
                        load: wgpu::LoadOp::Clear(frame.clear),
                        store: wgpu::StoreOp::Store,
                    },
                })],
                depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                    view: &frame.depth,
                    depth_ops: Some(wgpu::Operations {
                        load: wgpu::LoadOp::Clear(1.0),
                        store: wgpu::StoreOp::Store,
                    }),
                    stencil_ops: None,
                }),
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            });
            pass.set_pipeline(&frame.pipeline);
            pass.set_bind_group(0, &frame.frame_bind_group, &[]);
            for draw in &frame.draws {
                pass.set_bind_group(1, &draw.bind_group, &[]);
                pass.set_vertex_buffer(0, draw.vertices.slice(..));
                pass.draw(0..draw.count, 0..1);
            }
        }
        self.queue.submit([encoder.finish()]);
    }

    /// Makes `scene` ready to draw into views of `format` (see [`Frame`]).
    ///
    /// # Errors
    /// As [`Gpu::render`].
    pub fn frame(
        &self,
        scene: &Scene,
        options: &Options,
        format: wgpu::TextureFormat,
    ) -> Result<Frame, GpuError> {
        let prepared = prepare(scene, options)?;
        let Prepared { width, height, shading, features, shader, frame: uniform, lights, objects } =
            prepared;

        let device = &self.device;
        prepare::check_buffers(&objects, device.limits().max_buffer_size)?;
        let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);

        // Frame uniforms and lights.
        let frame_buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("cg-gpu frame"),
            contents: bytemuck::bytes_of(&uniform),
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
        });
        let light_data = if lights.is_empty() { vec![GpuLight::default()] } else { lights };
        let light_buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("cg-gpu lights"),
            contents: bytemuck::cast_slice(&light_data),
            usage: wgpu::BufferUsages::STORAGE,
        });
        let frame_bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("cg-gpu frame"),
            layout: &self.frame_layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: frame_buffer.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 1, resource: light_buffer.as_entire_binding() },
            ],
        });

        // Textures: one per scene texture that an object uses, and a white texel for the rest.
        let mut textures: HashMap<usize, wgpu::TextureView> = HashMap::new();
        let white = features.textures.then(|| self.upload_texture(1, 1, &[[255; 4]]));

        let mut draws = Vec::with_capacity(objects.len());
        for object in objects {
            let uniform_buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("cg-gpu object"),
                contents: bytemuck::bytes_of(&object.uniform),
                usage: wgpu::BufferUsages::UNIFORM,
            });
            let bind_group = if let Some(white) = &white {
                let (view, sampler) = match object.texture {
                    Some((index, sampler)) => {
                        let texture = &scene.textures[index];
                        let view = textures
                            .entry(index)
                            .or_insert_with(|| {
                                self.upload_texture(texture.width, texture.height, &texture.texels)
                            })
                            .clone();
                        (view, self.sampler(sampler))
                    }
                    None => (white.clone(), self.sampler(cg_core::texture::Sampler::default())),
                };
                device.create_bind_group(&wgpu::BindGroupDescriptor {
                    label: Some("cg-gpu object"),
                    layout: &self.object_layout_textured,
                    entries: &[
                        wgpu::BindGroupEntry {
                            binding: 0,
                            resource: uniform_buffer.as_entire_binding(),
                        },
                        wgpu::BindGroupEntry {
                            binding: 1,
                            resource: wgpu::BindingResource::TextureView(&view),
                        },
                        wgpu::BindGroupEntry {
                            binding: 2,
                            resource: wgpu::BindingResource::Sampler(&sampler),
                        },
                    ],
                })
            } else {
                device.create_bind_group(&wgpu::BindGroupDescriptor {
                    label: Some("cg-gpu object"),
                    layout: &self.object_layout,
                    entries: &[wgpu::BindGroupEntry {
                        binding: 0,
                        resource: uniform_buffer.as_entire_binding(),
                    }],
                })
            };
            let buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("cg-gpu vertices"),
                contents: bytemuck::cast_slice(&object.vertices),
                usage: wgpu::BufferUsages::VERTEX,
            });
            draws.push(DrawCall {
                vertices: buffer,
                count: object.vertices.len() as u32,
                bind_group,
            });
        }

        let pipeline = self.pipeline(PipelineKey {
            shader: shader.clone(),
            cull: scene.cull_back_faces,
            textured: features.textures,
            format,
        });
        let depth = self.depth_buffer(width, height);
        if let Some(e) = pollster::block_on(scope.pop()) {
            return Err(GpuError::Wgpu(e.to_string()));
        }
        let c = scene.clear_color;
        Ok(Frame {
            width,
            height,
            format,
            shading,
            features,
            shader,
            clear: wgpu::Color { r: c.x.into(), g: c.y.into(), b: c.z.into(), a: 1.0 },
            pipeline,
            frame_bind_group,
            frame_buffer,
            light_count: uniform.light_count[0],
            draws,
            depth,
            readback: Mutex::new(None),
        })
    }

    /// Moves `frame` to `scene`'s current camera and projection at `width × height` pixels (a
    /// window's orbit drag or resize), without rebuilding it: rewrites the frame's uniforms and,
    /// for a new size, its depth buffer. Objects, materials and lights stay as they were when
    /// the frame was made; for changed geometry make a new frame with [`Gpu::frame`].
    ///
    /// # Errors
    /// A zero or too large size, an invalid camera or projection.
    pub fn update_view(
        &self,
        frame: &mut Frame,
        scene: &Scene,
        width: u32,
        height: u32,
    ) -> Result<(), GpuError> {
        check_size(width, height)?;
        let uniform = FrameUniform {
            light_count: [frame.light_count, 0, 0, 0],
            ..frame_uniform(scene, width, height)?
        };
        self.queue.write_buffer(&frame.frame_buffer, 0, bytemuck::bytes_of(&uniform));
        if (width, height) != (frame.width, frame.height) {
            frame.depth = self.depth_buffer(width, height);
            frame.width = width;
            frame.height = height;
        }
        Ok(())
    }

    fn depth_buffer(&self, width: u32, height: u32) -> wgpu::TextureView {
        self.device
            .create_texture(&wgpu::TextureDescriptor {
                label: Some("cg-gpu depth"),
                size: wgpu::Extent3d { width, height, depth_or_array_layers: 1 },
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format: DEPTH_FORMAT,
                usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
                view_formats: &[],
            })
            .create_view(&wgpu::TextureViewDescriptor::default())
    }

    fn upload_texture(&self, width: u32, height: u32, texels: &[[u8; 4]]) -> wgpu::TextureView {
        let size = wgpu::Extent3d { width, height, depth_or_array_layers: 1 };
        let texture = self.device.create_texture(&wgpu::TextureDescriptor {
            label: Some("cg-gpu texture"),
            size,
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: wgpu::TextureFormat::Rgba8Unorm,
            usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
            view_formats: &[],
        });
        // Row 0 of the kit's texture is its bottom row, at t = 0: uploaded as row 0, sampled at
        // v = t, so no flip is needed.
        self.queue.write_texture(
            wgpu::TexelCopyTextureInfo {
                texture: &texture,
                mip_level: 0,
                origin: wgpu::Origin3d::ZERO,
                aspect: wgpu::TextureAspect::All,
            },
            bytemuck::cast_slice(texels),
            wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(width * 4),
                rows_per_image: Some(height),
            },
            size,
        );
        texture.create_view(&wgpu::TextureViewDescriptor::default())
    }

    fn sampler(&self, s: cg_core::texture::Sampler) -> wgpu::Sampler {
        let address = |w: Wrap| match w {
            Wrap::Repeat => wgpu::AddressMode::Repeat,
            Wrap::Clamp => wgpu::AddressMode::ClampToEdge,
        };
        let filter = match s.filter {
            Filter::Nearest => wgpu::FilterMode::Nearest,
            Filter::Bilinear => wgpu::FilterMode::Linear,
        };
        self.device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("cg-gpu sampler"),
            address_mode_u: address(s.wrap_u),
            address_mode_v: address(s.wrap_v),
            mag_filter: filter,
            min_filter: filter,
            ..wgpu::SamplerDescriptor::default()
        })
    }

    fn pipeline(&self, key: PipelineKey) -> wgpu::RenderPipeline {
        let mut cache = self.pipelines.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
        if let Some(p) = cache.get(&key) {
            return p.clone();
        }
        let device = &self.device;
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("cg-gpu generated"),
            source: wgpu::ShaderSource::Wgsl(key.shader.as_str().into()),
        });
        let object_layout =
            if key.textured { &self.object_layout_textured } else { &self.object_layout };
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("cg-gpu"),
            bind_group_layouts: &[Some(&self.frame_layout), Some(object_layout)],
            immediate_size: 0,
        });
        let attributes = wgpu::vertex_attr_array![
            0 => Float32x3, 1 => Float32x3, 2 => Float32x3, 3 => Float32x3, 4 => Float32x2,
            5 => Float32x3
        ];
        let pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some("cg-gpu"),
            layout: Some(&layout),
            vertex: wgpu::VertexState {
                module: &module,
                entry_point: Some("vs_main"),
                compilation_options: wgpu::PipelineCompilationOptions::default(),
                buffers: &[Some(wgpu::VertexBufferLayout {
                    array_stride: std::mem::size_of::<GpuVertex>() as u64,
                    step_mode: wgpu::VertexStepMode::Vertex,
                    attributes: &attributes,
                })],
            },
            primitive: wgpu::PrimitiveState {
                topology: wgpu::PrimitiveTopology::TriangleList,
                front_face: wgpu::FrontFace::Ccw,
                cull_mode: key.cull.then_some(wgpu::Face::Back),
                ..wgpu::PrimitiveState::default()
            },
            depth_stencil: Some(wgpu::DepthStencilState {
                format: DEPTH_FORMAT,
                depth_write_enabled: Some(true),
                depth_compare: Some(wgpu::CompareFunction::Less),
                stencil: wgpu::StencilState::default(),
                bias: wgpu::DepthBiasState::default(),
            }),
            multisample: wgpu::MultisampleState::default(),
            fragment: Some(wgpu::FragmentState {
                module: &module,
                entry_point: Some("fs_main"),
                compilation_options: wgpu::PipelineCompilationOptions::default(),
                targets: &[Some(wgpu::ColorTargetState {
                    format: key.format,
                    blend: None,
                    write_mask: wgpu::ColorWrites::ALL,
                })],
            }),
            multiview_mask: None,
            cache: None,
        });
        cache.insert(key, pipeline.clone());
        pipeline
    }
}
