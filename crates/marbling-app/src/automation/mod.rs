//! What tests and tools read: the `data-*` hooks on the page's `<body>`, the memory
//! report and the panic guard that writes the waiting autosave.

pub(crate) mod hooks;
pub(crate) mod memory;
pub mod panic_guard;
