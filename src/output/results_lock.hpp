// One writer per output: every command takes a lock on its output before
// any work, an flock on "<output>.lock" next to it with the holder's pid,
// host, command and start time in it, and keeps it until the process ends
// (or the results folder that took it is done); a second run into the same
// output is refused naming who holds it. The kernel releases the lock when
// its process dies, so a killed run never blocks the next (its lock file
// stays, and the next run takes it over, saying whose it was, and removes
// it when done). Used by output/results_folder.cpp.
#pragma once

#include <filesystem>

namespace coremodal::results_lock {

// Takes the lock of `output` (a checked output path) unless this process
// holds it already; returns whether it was taken now. Throws InputError
// naming the holder when another process holds it.
bool take_lock(const std::filesystem::path& output);

// Releases the lock of `output` taken by take_lock (its file removed, the
// folders made for it removed if still empty); nothing if not held.
void release_lock(const std::filesystem::path& output);

}  // namespace coremodal::results_lock
