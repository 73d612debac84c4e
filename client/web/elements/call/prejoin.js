// <inkwire-call>'s pre-join (SPEC F7, F15): the camera's preview and the microphone (or the
// reason there are none, `reason`), captured off the page's thread (call/voice.js) while the
// person picks a name and takes the neutral photo; the renderer loads meanwhile. A mixin over
// SessionElement (one feature a file, as the turntable element).
import { photoOf } from '../../call/camera.js';
import { CallLink, voiceUnsupported } from '../../call/voice.js';

export const PrejoinMixin = (Base) => class extends Base {
  // Pre-join: the camera and microphone (or the reason there are none), and the renderer.
  async start() {
    this.leave();
    this.nameInput.value = this.getAttribute('name') ?? this.nameInput.value;
    this.muted = this.hasAttribute('muted');
    this.cameraOff = this.getAttribute('camera') === 'off';
    this.reason = voiceUnsupported();
    this.hasVoice = false;
    this.tilesReady ??= this.tiles.load(this.serverUrl());
    this.tilesReady.catch((error) => this.fail(`faces cannot be drawn: ${error.message}`));
    this.link?.close();
    // The worker and the audio graph are made while the person is in pre-join.
    const link = (this.link = new CallLink({ onLevel: (db) => (this.level.value = db) }));
    try {
      this.media = await navigator.mediaDevices.getUserMedia({ video: !this.cameraOff, audio: !this.reason });
    } catch (error) {
      this.media = null;
      this.reason ||= `no camera or microphone (${error.message}): you will join as a listener`;
    }
    const video = this.media?.getVideoTracks()[0], audio = this.media?.getAudioTracks()[0];
    if (video) this.preview.srcObject = new MediaStream([video]);
    this.preview.hidden = !video;
    this.reason ||= await link.reason;
    if (audio && !this.reason) {
      try {
        await link.capture(audio);
        this.hasVoice = true;
        // The microphone may come after a quick Join: the call hears of it now.
        if (this.hasAttribute('joined')) this.publish();
      } catch (error) {
        this.reason = `${error.message}: you will join without voice`;
      }
    }
    // Embedded in a page that is not cross-origin isolated, the voice still flows, through message
    // ports instead of shared rings: said, since a busy page then may hold it back in some engines.
    this.isolationNote = link.shared ? '' : 'this page is not cross-origin isolated: the voice goes through message ports';
    if (this.reason) this.message.textContent = this.reason;
    else if (this.isolationNote) this.message.textContent = this.isolationNote;
    this.voiceReason = this.reason;  // what a connection's failure said goes once it is in the call
  }

  async takePhoto() {
    if (!this.preview.videoWidth) return;
    this.photo = await photoOf(this.preview);
    this.photoImg.src = URL.createObjectURL(new Blob([this.photo], { type: 'image/jpeg' }));
    if (this.session && this.hasAttribute('joined')) this.session.send({ type: 'neutral-photo', jpeg: this.photo });
  }
};
