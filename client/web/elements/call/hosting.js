// <inkwire-call>'s host (SPEC N6-N7): a room opened by joining it (the `open-room` attribute),
// the host key the server gives its opener kept by this browser (localStorage, per server and
// room) and given as the token on every join after, so a reload or a lost connection finds the
// host again; the host's controls: lock or open the room, remove a member, set the call's style.
// What others may not do the server refuses, and the element says the reason. A mixin over
// SessionElement (one feature a file).
import { RoomAction } from '../../protocol/messages.js';

const storageKey = (server, room) => `inkwire-host-key ${server} ${room}`;

export const HostingMixin = (Base) => class extends Base {
  // The key this browser holds for the room, if any (storage may be off: then none).
  storedHostKey() {
    try {
      return localStorage.getItem(storageKey(this.serverUrl(), this.getAttribute('session') ?? '')) ?? '';
    } catch {
      return '';
    }
  }

  keepHostKey(key) {
    try {
      localStorage.setItem(storageKey(this.serverUrl(), this.getAttribute('session') ?? ''), key);
    } catch {
      // no storage here: host until the page goes
    }
    this.hostKey = key;
  }

  forgetHostKey() {
    try {
      localStorage.removeItem(storageKey(this.serverUrl(), this.getAttribute('session') ?? ''));
    } catch {}
    this.hostKey = '';
  }

  // The token a join gives: this browser's host key for the room, else the `token` attribute.
  joinTokenForRoom() {
    this.hostKey ||= this.storedHostKey();
    return this.hostKey || this.joinToken();
  }

  // Whether this member is the room's host (the server's roster says so).
  get isHost() { return !!this.roster?.you && this.roster.host === this.roster.you; }
  get locked() { return !!this.roster?.locked; }

  // The host's controls follow the roster: shown to the host, hidden from everyone else.
  showHostControls() {
    this.lockButton.hidden = !this.isHost;
    this.lockButton.textContent = this.locked ? 'Open room' : 'Lock room';
    this.styleSelect.hidden = !this.isHost;
    this.lockNote.textContent = this.locked ? 'locked: nobody new can join' : '';
  }

  lockRoom(locked) { this.session?.send({ type: 'room-control', action: locked ? RoomAction.lock : RoomAction.unlock, member: 0 }); }
  removeMember(member) { this.session?.send({ type: 'room-control', action: RoomAction.remove, member }); }
  // The call's style for everyone (the host's; the server refuses it from others).
  setCallStyle(renderer) { this.session?.send({ type: 'style-change', renderer, settings: [] }); }

  // Under each other member's tile, the host's button to remove them.
  decorateCaption(div, tile) {
    if (!this.isHost || tile.you) return;
    const remove = document.createElement('button');
    remove.className = 'remove';
    remove.textContent = '×';
    remove.title = `Remove ${tile.name} from the call`;
    remove.setAttribute('aria-label', remove.title);
    remove.addEventListener('click', () => this.removeMember(tile.member));
    div.prepend(remove);
  }
};
