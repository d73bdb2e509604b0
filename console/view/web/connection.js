// The page's one WebSocket to the bridge (PROTOCOL.md): requests with ids, messages by type.

import { authAnswer } from "./auth.js";

export class Connection {
  constructor(url, token) {
    this.url = url;
    this.token = token; // from the URL fragment, or null
    this.authExpect = null;
    this.readOnly = false;
    this.nextId = 1;
    this.pending = new Map(); // id -> {resolve}
    this.handlers = new Map(); // message type -> [fn]
    this.stateHandlers = [];
    this.state = "connecting";
    this.ws = null;
    this.retryMs = 500;
  }

  on(type, fn) {
    if (!this.handlers.has(type)) this.handlers.set(type, []);
    this.handlers.get(type).push(fn);
  }

  onState(fn) {
    this.stateHandlers.push(fn);
  }

  setState(state) {
    this.state = state;
    for (const fn of this.stateHandlers) fn(state);
  }

  open() {
    this.setState("connecting");
    const ws = new WebSocket(this.url);
    this.ws = ws;
    this.final = null; // a state that retrying cannot change (a refused token)
    ws.onopen = () => {
      this.retryMs = 500;
      this.setState("open");
    };
    ws.onmessage = (ev) => this.dispatch(ev.data);
    ws.onclose = (ev) => {
      this.ws = null;
      this.failPending("connection closed");
      if (ev.code === 1008 && !this.final) this.final = "refused: wrong token";
      if (this.final) return this.setState(this.final);
      this.setState("disconnected");
      // The bridge may be restarting: try again, slower each time, up to 5 s apart.
      setTimeout(() => this.open(), this.retryMs);
      this.retryMs = Math.min(this.retryMs * 2, 5000);
    };
  }

  dispatch(text) {
    let msg;
    try {
      msg = JSON.parse(text);
    } catch (e) {
      console.warn("view: a message that is not JSON", text.slice(0, 80));
      return;
    }
    if (msg.type === "auth" || msg.type === "auth_ok") {
      this.authenticate(msg);
      return;
    }
    if (msg.type === "hello") this.setState(this.readOnly ? "connected (read only)" : "connected");
    if ((msg.type === "reply" || msg.type === "value") && this.pending.has(msg.id)) {
      this.pending.get(msg.id).resolve(msg);
      this.pending.delete(msg.id);
    }
    for (const fn of this.handlers.get(msg.type) || []) fn(msg);
  }

  // Challenge-response: prove the token, then check the bridge's proof (PROTOCOL.md).
  authenticate(msg) {
    if (msg.type === "auth") {
      if (!this.token) {
        this.final = "needs token (open the page as /#token=...)";
        this.ws.close();
        return;
      }
      const answer = authAnswer(this.token, msg.nonce);
      this.authExpect = answer.expect;
      this.send(answer.message);
    } else if (msg.proof !== this.authExpect) {
      this.final = "refused: the bridge failed its token proof";
      this.ws.close();
    } else {
      this.readOnly = !!msg.read_only;
    }
  }

  failPending(why) {
    for (const p of this.pending.values()) p.resolve({ ok: false, output: "", error: why });
    this.pending.clear();
  }

  send(obj) {
    if (!this.ws || this.ws.readyState !== WebSocket.OPEN) return false;
    this.ws.send(JSON.stringify(obj));
    return true;
  }

  // A request answered by a reply/value with the same id; resolves with the reply.
  request(obj) {
    const id = this.nextId++;
    return new Promise((resolve) => {
      if (!this.send({ ...obj, id })) {
        resolve({ ok: false, output: "", error: "not connected" });
        return;
      }
      this.pending.set(id, { resolve });
    });
  }

  cmd(line) {
    return this.request({ op: "cmd", line });
  }

  get(key) {
    return this.request({ op: "get", key });
  }
}

// ws://host/ws for the page's own origin.
export function bridgeUrl(loc) {
  const scheme = loc.protocol === "https:" ? "wss:" : "ws:";
  return `${scheme}//${loc.host}/ws`;
}
