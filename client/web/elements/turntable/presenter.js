// <inkwire-turntable>'s presenter mode (SPEC T13), off unless asked for: with the attribute
// `present` the view goes to the session as object poses whenever it changes (only the
// product's editor may: a refused presenter stops), with `follow` the newest view a presenter
// sent replaces this one (a drag turns it until the next). Either opens the live part, a WebSocket
// to the session's server, when it is set (the product's files come over plain HTTP either way).
import { poseOfView, viewOfPose } from '../../common/turntable_pose.js';

export const PresenterMixin = (Base) => class extends Base {
  // The live part, opened once the element presents or follows and kept while it lives: a
  // presenter's views, and the refusal of a visitor who tries to present. A visitor who only
  // turns the product opens none.
  goLive() {
    if (this.session || !this.hasAttribute('session') || !(this.hasAttribute('present') || this.hasAttribute('follow'))) return;
    const live = this.openSession();
    this.liveJoined = false;
    live.addEventListener('refused', () => { this.presentRefused = true; });
    live.addEventListener('state', (e) => {
      if (e.detail.type === 'object-pose') this.follow(e.detail);
    });
    live.addEventListener('snapshot', (e) => {
      this.liveJoined = true;  // a presenter's view goes out from here on (nothing is sent before the join)
      this.follow(e.detail.object);
      this.redraw();
    }, { once: true });
  }

  // Following: the presenter's view replaces this one.
  follow(pose) {
    if (!this.hasAttribute('follow')) return;
    const { azimuth, elevation, zoom } = viewOfPose(pose);
    this.touched = true;  // no auto-spin of its own
    this.velocity = 0;
    this.elevation = elevation;
    this.zoom = zoom;
    this.azimuth = azimuth;
  }

  // Presenting: the view goes to the session whenever it changes, at most once a frame; a
  // presenter the server refused (only the product's editor presents) stops sending.
  present() {
    if (!this.hasAttribute('present') || this.presentRefused || !this.liveJoined || !this.snapshot) return;
    const view = [this._azimuth, this.elevation, this.zoom];
    if (this.presented && view.every((v, i) => v === this.presented[i])) return;
    this.presented = view;
    this.poseSequence = (this.poseSequence ?? 0) + 1;
    this.session.send(poseOfView(...view, this.poseSequence));
  }

};
