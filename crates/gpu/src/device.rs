//! Headless device creation: a real adapter if there is one, a software
//! adapter otherwise, and a clear message when there is none.

use std::fmt;

/// Set this environment variable to `1` to make a missing adapter a test
/// failure instead of a skip (CI sets it, after installing lavapipe).
pub const GPU_REQUIRED_VAR: &str = "GPU_REQUIRED";

/// Why no device could be made.
#[derive(Debug, thiserror::Error)]
pub enum GpuError {
    /// No adapter at all: neither hardware nor a software driver.
    #[error(
        "no GPU adapter found (neither hardware nor software); on Debian/Ubuntu \
         `apt-get install mesa-vulkan-drivers libvulkan1` provides the software \
         adapter lavapipe"
    )]
    NoAdapter,
    /// An adapter was found but refused to open a device.
    #[error("the adapter {adapter} could not open a device: {source}")]
    Device {
        /// The adapter's name.
        adapter: String,
        /// What wgpu reported.
        source: wgpu::RequestDeviceError,
    },
    /// A buffer could not be mapped for reading.
    #[error("mapping a buffer for readback failed: {0}")]
    Map(#[from] wgpu::BufferAsyncError),
    /// A mapped buffer could not be viewed.
    #[error("reading a mapped buffer failed: {0}")]
    MapRange(String),
    /// Waiting for the GPU failed.
    #[error("waiting for the GPU failed: {0}")]
    Poll(#[from] wgpu::PollError),
    /// A shader or pipeline failed validation (its message names the line).
    #[error("{what} failed validation:\n{message}")]
    Validation {
        /// What was being created.
        what: String,
        /// wgpu's message, with the WGSL line for shader errors.
        message: String,
    },
}

/// An adapter with its device and queue.
pub struct Gpu {
    /// The adapter's description: name, backend, device type.
    pub info: wgpu::AdapterInfo,
    /// The logical device.
    pub device: wgpu::Device,
    /// Its queue.
    pub queue: wgpu::Queue,
}

impl fmt::Debug for Gpu {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Gpu").field("info", &self.info).finish()
    }
}

impl Gpu {
    /// Opens a device on the best adapter: a high-performance hardware
    /// adapter when one exists, otherwise the software fallback adapter.
    ///
    /// `WGPU_BACKEND` (e.g. `vulkan`, `gl`) and `WGPU_ADAPTER_NAME` narrow the
    /// choice, as in every wgpu program.
    pub fn new() -> Result<Self, GpuError> {
        let instance =
            wgpu::Instance::new(wgpu::InstanceDescriptor::new_without_display_handle().with_env());
        let mut options = wgpu::RequestAdapterOptions {
            power_preference: wgpu::PowerPreference::HighPerformance,
            force_fallback_adapter: false,
            compatible_surface: None,
            apply_limit_buckets: false,
        };
        let adapter = match pollster::block_on(instance.request_adapter(&options)) {
            Ok(adapter) => adapter,
            Err(_) => {
                options.force_fallback_adapter = true;
                pollster::block_on(instance.request_adapter(&options))
                    .map_err(|_| GpuError::NoAdapter)?
            }
        };
        let info = adapter.get_info();
        let descriptor = wgpu::DeviceDescriptor {
            label: Some("course device"),
            required_features: wgpu::Features::empty(),
            required_limits: wgpu::Limits::downlevel_defaults().using_resolution(adapter.limits()),
            ..Default::default()
        };
        let (device, queue) =
            pollster::block_on(adapter.request_device(&descriptor)).map_err(|source| {
                GpuError::Device {
                    adapter: info.name.clone(),
                    source,
                }
            })?;
        Ok(Self {
            info,
            device,
            queue,
        })
    }

    /// The device for a test, or `None` with a skip line on stderr when there
    /// is no adapter.
    ///
    /// # Panics
    /// When there is no adapter and [`GPU_REQUIRED_VAR`] is `1`: where a GPU
    /// (or lavapipe) is promised, its absence is a failure, not a skip.
    #[must_use]
    pub fn for_tests() -> Option<Self> {
        match Self::new() {
            Ok(gpu) => Some(gpu),
            Err(e) => {
                let required = std::env::var(GPU_REQUIRED_VAR).is_ok_and(|v| v == "1");
                assert!(!required, "{GPU_REQUIRED_VAR}=1 but {e}");
                eprintln!("SKIPPED (no GPU): {e}; set {GPU_REQUIRED_VAR}=1 to make this a failure");
                None
            }
        }
    }

    /// A one-line description: `name (backend, device type)`, so that figures
    /// from a software adapter are never mistaken for GPU figures.
    #[must_use]
    pub fn describe(&self) -> String {
        format!(
            "{} ({:?}, {:?})",
            self.info.name, self.info.backend, self.info.device_type
        )
    }

    /// Whether the adapter is a software rasterizer running on the CPU.
    #[must_use]
    pub fn is_software(&self) -> bool {
        self.info.device_type == wgpu::DeviceType::Cpu
    }

    /// Compiles WGSL, returning wgpu's validation message (with line
    /// numbers) as an error instead of panicking.
    pub fn shader(&self, label: &str, wgsl: &str) -> Result<wgpu::ShaderModule, GpuError> {
        let scope = self.device.push_error_scope(wgpu::ErrorFilter::Validation);
        let module = self
            .device
            .create_shader_module(wgpu::ShaderModuleDescriptor {
                label: Some(label),
                source: wgpu::ShaderSource::Wgsl(wgsl.into()),
            });
        self.check(scope, label)?;
        Ok(module)
    }

    /// Runs `make` inside a validation error scope: a pipeline whose shader
    /// interface does not match comes back as an error, not a panic.
    pub fn validated<T>(&self, what: &str, make: impl FnOnce() -> T) -> Result<T, GpuError> {
        let scope = self.device.push_error_scope(wgpu::ErrorFilter::Validation);
        let value = make();
        self.check(scope, what)?;
        Ok(value)
    }

    fn check(&self, scope: wgpu::ErrorScopeGuard, what: &str) -> Result<(), GpuError> {
        match pollster::block_on(scope.pop()) {
            None => Ok(()),
            Some(error) => Err(GpuError::Validation {
                what: what.to_owned(),
                message: error.to_string(),
            }),
        }
    }

    /// Blocks until the GPU has finished all submitted work.
    pub fn wait(&self) -> Result<(), GpuError> {
        self.device.poll(wgpu::PollType::wait_indefinitely())?;
        Ok(())
    }
}
