//! Why a run stopped early: bad input or physics gone wrong (the exit
//! codes of `crashsim run`). The solver and the output hooks return it.

/// Why a run stopped early.
#[derive(Debug)]
pub enum RunError {
    /// Bad or unsupported input (exit code 2).
    Input(String),
    /// Physics went wrong at run time (exit code 3).
    Physics(String),
}

impl RunError {
    pub fn exit_code(&self) -> u8 {
        match self {
            RunError::Input(_) => 2,
            RunError::Physics(_) => 3,
        }
    }
    pub fn message(&self) -> &str {
        match self {
            RunError::Input(m) | RunError::Physics(m) => m,
        }
    }
}
