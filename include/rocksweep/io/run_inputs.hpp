#pragma once
/// The files a run reads, so that no output can replace one of them. Each command notes its
/// inputs as it learns them (the options that name an existing file, the records a suite lists,
/// a design's round files); every OutputClaim then refuses an output that is one of them.
/// Identity is the file's (device, inode), taken when the input is noted: a hard link, a
/// symbolic link or another spelling of the same path is caught, a different file of the same
/// name is not mistaken for it.
#include <string>

namespace rocksweep {

/// Notes `path`, named by `what` in messages ("--config", "--suite's record elcentro"), as read
/// by this run. A path that does not exist (yet) is ignored.
void note_input(const std::string& what, const std::string& path);

/// Throws InputError(field, path, ...) naming the input if `path` exists and is the same file as
/// one noted. Called by OutputClaim before it creates anything.
void refuse_input_as_output(const std::string& field, const std::string& path);

/// Throws InputError(field, path, ...) as refuse_input_as_output if `path` exists and is the
/// same file as `input` (named by `what`), without noting it: for an input that only some claims
/// must respect (a design's round files are the outputs of its rounds, and inputs of its own file).
void refuse_same_file(const std::string& field, const std::string& path, const std::string& what, const std::string& input);

/// Forgets every noted input (each command line of the process starts afresh).
void forget_inputs();

}  // namespace rocksweep
