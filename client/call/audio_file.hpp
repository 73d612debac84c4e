#pragma once
// Sound files for calls: a WAV file read as mono samples at the call's rate (48 kHz: 16-bit or
// 32-bit float PCM, any channel count mixed down, any rate resampled with libsamplerate), and
// mono 48 kHz 16-bit WAV written (a call's received sound, --audio-out).
#include <filesystem>
#include <vector>

namespace inkwire {

inline constexpr int kCallRate = 48000;

// Throws inkwire::Error with the reason when the file is no WAV this reads.
std::vector<float> read_wav_mono(const std::filesystem::path& file, int rate = kCallRate);
// Throws inkwire::Error when the file cannot be written.
void write_wav_mono(const std::filesystem::path& file, const std::vector<float>& samples, int rate = kCallRate);

}  // namespace inkwire
