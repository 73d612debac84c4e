// A call's grid in the page (SPEC F11, F16): every tile drawn by the native client's CallGrid
// compiled into the module (client/web/module/face_module.cpp), in the session's style; the
// captions, which the grid says where to put and what to say (caption_of in C++), are the page's
// own text under the tiles. Made in pre-join, so the module is there when the call is. The grid is
// drawn again only when something changed, a face is tweening or a style paints frame after
// frame: a call's page has camera crops to make on its thread too.
import { fitCanvas, lendBytes, loadRenderModule } from '../session_element.js';

export class CallTiles {
  constructor(canvas, captions) {
    this.canvas = canvas;
    this.captions = captions;
    this.shown = '';
    this.changed = true;  // something to draw
    this.tweenUntil = 0;
  }

  // Whether the next animation frame has anything new to draw.
  due() { return fitCanvas(this.canvas) || this.changed || performance.now() < this.tweenUntil || this.view.animates(); }

  // Loads the module from `server` (a ws:// address); throws with the reason it cannot.
  async load(server) {
    ({ module: this.module, bytes: this.moduleBytes } = await loadRenderModule(server, this.canvas));
    this.view = new this.module.CallGridView('!canvas');
    const reason = this.view.error();
    if (reason) throw new Error(reason);
    this.names = JSON.parse(this.module.expressionNamesJson());
  }

  // A member's neutral photo (its file's bytes) and landmarks (the server's JSON text).
  setMemberFace(member, photo, landmarks) {
    const reason = lendBytes(this.module, photo, (address, size) => this.view.setMemberFace(member, address, size, landmarks));
    if (reason) throw new Error(reason);
    this.changed = true;
  }

  setRoster(roster) {
    const reason = this.view.setRoster(JSON.stringify({ you: roster.you, members: roster.members.map(({ assets, ...m }) => m) }));
    if (reason) throw new Error(reason);
    this.changed = true;
  }

  // The session's style ({renderer, settings}); "" or why it is refused.
  setStyle(style) {
    this.changed = true;
    return this.view.setStyle(style.renderer, JSON.stringify(style.settings ?? []));
  }

  // A member's face as a member-layers message says it (layers and head pose), or a member-face's
  // one code.
  setFace(member, face) {
    if (face.type === 'member-face') this.view.setFace(member, face.expression.code, face.expression.intensity, face.yaw, face.pitch, face.roll);
    else this.view.setLayers(member, face.expression.code, face.expression.intensity, face.mouth.code, face.mouth.intensity, face.eye_left, face.eye_right,
                             face.yaw, face.pitch, face.roll);
    this.tweenUntil = performance.now() + 250;  // the face tweens for 100 ms
  }

  // The name of the expression a member's tile shows (the one code that says most of its
  // layers; null without a face on its tile), and the face it is drawn to ({pose, eyes, layers}).
  expressionOf(member) { return JSON.parse(this.view.expressionJson(member))?.name ?? null; }
  faceOf(member) { return JSON.parse(this.view.faceJson(member)); }

  // One frame at the canvas's size in device pixels, then the captions under the tiles. Returns
  // whether a face was drawn.
  // `decorate(div, tile)`, when given, adds to each tile's caption (the host's remove button).
  draw(seconds, decorate = null) {
    fitCanvas(this.canvas);
    const ratio = window.devicePixelRatio || 1;
    const reason = this.view.draw(seconds);
    if (reason) throw new Error(reason);
    this.changed = false;
    const tiles = JSON.parse(this.view.tilesJson());
    const text = JSON.stringify([tiles.map((t) => [t.caption, t.speaking, t.rect]), !!decorate]);
    if (text !== this.shown || decorate !== this.decorate) {
      this.decorate = decorate;
      this.shown = text;
      this.captions.replaceChildren(...tiles.map((t) => {
        const div = document.createElement('div');
        div.className = `caption${t.speaking ? ' speaking' : ''}`;
        const [x, y, w, h] = t.rect.map((v) => v / ratio);
        Object.assign(div.style, { left: `${x}px`, top: `${y + h + 2}px`, width: `${w}px` });
        div.textContent = t.caption;
        decorate?.(div, t);
        return div;
      }));
    }
    return tiles.some((t) => t.has_face);
  }
}
