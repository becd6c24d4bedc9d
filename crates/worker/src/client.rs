//! The trusted side: start a worker, call its functions one at a time, each within a time
//! budget; a call that runs over, or a worker that dies, fails that call alone.

use std::io::{BufReader, Read, Write};
use std::path::PathBuf;
use std::process::{Child, ChildStdin, Command, Stdio};
use std::sync::mpsc::{Receiver, RecvTimeoutError, channel};
use std::time::Duration;

use crate::{Call, Reply, frame};

/// Why a call gave no value.
#[derive(Clone, Debug, PartialEq)]
pub enum CallError {
    /// The function panicked: `message` is `not yet implemented: …` for a `todo!()`.
    Panicked {
        /// The panic's message.
        message: String,
        /// Where, when known.
        location: Option<String>,
    },
    /// It ran past its time budget; the worker was stopped.
    TimedOut(Duration),
    /// The worker ended during the call (an abort, a memory limit, a stack overflow): how, and
    /// the end of what it wrote on stderr.
    Crashed {
        /// The exit status, as the system describes it.
        status: String,
        /// The end of its stderr.
        stderr: String,
    },
    /// The worker could not be started, or its reply did not read (a mismatch of kit and
    /// worker, or a student's program that wrote a frame of its own).
    Broken(String),
}

/// A running worker and what is needed to start another.
pub struct Worker {
    program: PathBuf,
    args: Vec<String>,
    running: Option<Running>,
    /// What the student's functions printed on stdout, in order.
    pub printed: Vec<u8>,
}

struct Running {
    child: Child,
    stdin: ChildStdin,
    /// Each frame read from the worker's stdout (payload or end, and the prints before it).
    replies: Receiver<std::io::Result<frame::Read>>,
}

impl std::fmt::Debug for Worker {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Worker").field("program", &self.program).finish_non_exhaustive()
    }
}

impl Worker {
    /// A worker that runs `program args…` (started at the first call).
    #[must_use]
    pub fn new(program: impl Into<PathBuf>, args: Vec<String>) -> Worker {
        Worker { program: program.into(), args, running: None, printed: Vec::new() }
    }

    fn start(&mut self) -> Result<&mut Running, CallError> {
        if self.running.is_none() {
            let mut child = Command::new(&self.program)
                .args(&self.args)
                .stdin(Stdio::piped())
                .stdout(Stdio::piped())
                .stderr(Stdio::piped())
                .spawn()
                .map_err(|e| CallError::Broken(format!("{}: {e}", self.program.display())))?;
            let (Some(stdin), Some(stdout)) = (child.stdin.take(), child.stdout.take()) else {
                return Err(CallError::Broken("no pipes to the worker".to_owned()));
            };
            let (send, replies) = channel();
            std::thread::spawn(move || {
                let mut out = BufReader::new(stdout);
                loop {
                    let next = frame::read(&mut out);
                    let end = !matches!(next, Ok((Some(_), _)));
                    if send.send(next).is_err() || end {
                        return;
                    }
                }
            });
            self.running = Some(Running { child, stdin, replies });
        }
        self.running.as_mut().ok_or_else(|| CallError::Broken("not started".to_owned()))
    }

    /// Stops the worker (the next call starts a fresh one).
    pub fn stop(&mut self) {
        if let Some(mut r) = self.running.take() {
            let _ = r.child.kill();
            let _ = r.child.wait();
        }
    }

    /// Calls `function` with `args` and waits at most `budget` for its reply.
    ///
    /// # Errors
    /// The function panicked, ran over, crashed the worker, or the reply did not read.
    pub fn call<A, R>(&mut self, function: &str, args: &A, budget: Duration) -> Result<R, CallError>
    where
        A: serde::Serialize,
        R: serde::de::DeserializeOwned,
    {
        let call = Call {
            function: function.to_owned(),
            args: serde_json::to_value(args).map_err(|e| CallError::Broken(e.to_string()))?,
        };
        let bytes = serde_json::to_vec(&call).map_err(|e| CallError::Broken(e.to_string()))?;
        let running = self.start()?;
        let sent = frame::write(&mut running.stdin, &bytes);
        let answer = match sent {
            Err(_) => Err(RecvTimeoutError::Disconnected),
            Ok(()) => running.replies.recv_timeout(budget),
        };
        let payload = match answer {
            Ok(Ok((Some(payload), printed))) => {
                self.printed.extend_from_slice(&printed);
                payload
            }
            Ok(Ok((None, printed))) => {
                self.printed.extend_from_slice(&printed);
                return Err(self.crashed());
            }
            Ok(Err(e)) => {
                self.stop();
                return Err(CallError::Broken(format!("the worker's reply: {e}")));
            }
            Err(RecvTimeoutError::Timeout) => {
                self.stop();
                return Err(CallError::TimedOut(budget));
            }
            Err(RecvTimeoutError::Disconnected) => return Err(self.crashed()),
        };
        match serde_json::from_slice::<Reply>(&payload) {
            Ok(Reply::Value(v)) => serde_json::from_value(v).map_err(|e| {
                CallError::Broken(format!("{function} returned a value of another type: {e}"))
            }),
            Ok(Reply::Panicked { message, location }) => {
                Err(CallError::Panicked { message, location })
            }
            Ok(Reply::BadArguments(why)) => Err(CallError::Broken(format!("{function}: {why}"))),
            Ok(Reply::Unknown(name)) => Err(CallError::Broken(format!("no function {name}"))),
            Err(e) => {
                self.stop();
                Err(CallError::Broken(format!("the worker's reply does not read: {e}")))
            }
        }
    }

    /// The worker ended during a call: how, with the end of its stderr.
    fn crashed(&mut self) -> CallError {
        let Some(mut r) = self.running.take() else {
            return CallError::Broken("the worker is not running".to_owned());
        };
        let status = r.child.wait().map_or_else(|e| e.to_string(), |s| s.to_string());
        let mut stderr = String::new();
        if let Some(mut e) = r.child.stderr.take() {
            let _ = e.read_to_string(&mut stderr);
        }
        let tail: String =
            stderr.chars().rev().take(2000).collect::<Vec<_>>().into_iter().rev().collect();
        CallError::Crashed { status, stderr: tail }
    }
}

impl Drop for Worker {
    fn drop(&mut self) {
        if let Some(r) = self.running.as_mut() {
            let _ = r.stdin.flush();
        }
        self.stop();
    }
}
