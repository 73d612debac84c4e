#include "client/call/speaker.hpp"

#include <algorithm>

#include <portaudio.h>

#include "client/call/audio_file.hpp"

namespace inkwire {

Speaker::Speaker() {
  if (Pa_Initialize() != paNoError) {
    reason_ = "no sound output: PortAudio cannot start";
    return;
  }
  initialised_ = true;
  if (Pa_GetDefaultOutputDevice() == paNoDevice) {
    reason_ = "no sound output device: the call is silent here";
    return;
  }
  PaStream* stream = nullptr;
  const PaError e = Pa_OpenDefaultStream(&stream, 0, 1, paFloat32, kCallRate, paFramesPerBufferUnspecified, nullptr, nullptr);
  if (e != paNoError || Pa_StartStream(stream) != paNoError) {
    reason_ = std::string("no sound output: ") + Pa_GetErrorText(e);
    if (stream) Pa_CloseStream(stream);
    return;
  }
  stream_ = stream;
}

Speaker::~Speaker() {
  if (stream_) Pa_CloseStream(static_cast<PaStream*>(stream_));
  if (initialised_) Pa_Terminate();
}

void Speaker::play(std::span<const float> samples) {
  if (!stream_ || samples.empty()) return;
  const long room = Pa_GetStreamWriteAvailable(static_cast<PaStream*>(stream_));
  const auto n = unsigned(std::clamp<long>(room, 0, long(samples.size())));
  if (n > 0) Pa_WriteStream(static_cast<PaStream*>(stream_), samples.data(), n);
}

}  // namespace inkwire
