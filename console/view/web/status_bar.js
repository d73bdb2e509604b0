// The status line (mode, target, sim time, running, real time, dropped, connection) and the
// run/pause/step/reset/realtime buttons of a local simulation.

const $ = (id) => document.getElementById(id);

export class StatusBar {
  constructor(consolePane) {
    this.consolePane = consolePane;
    this.realtime = false;
    this.dropped = 0;
    this.logT = null; // the shown log frame's time, read by the page (see log_sampler.js)
    $("btn-run").onclick = () => consolePane.run("run");
    $("btn-pause").onclick = () => consolePane.run("pause");
    $("btn-step").onclick = () => consolePane.run("step 1");
    $("btn-reset").onclick = () => consolePane.run("reset");
    $("btn-realtime").onclick = () => consolePane.run(`realtime ${this.realtime ? "off" : "on"}`);
  }

  setConnection(state) {
    const el = $("st-conn");
    el.textContent = state;
    el.dataset.state = state;
  }

  setHello(hello) {
    $("st-mode").textContent = hello.mode;
    $("st-target").textContent = hello.target;
    document.body.dataset.mode = hello.mode;
    this.setRunning(!hello.paused);
    this.setRealtime(hello.realtime);
  }

  setRunning(running) {
    const el = $("st-state");
    el.textContent = running ? "running" : "paused";
    el.dataset.running = running ? "1" : "0";
  }

  setRealtime(on) {
    this.realtime = !!on;
    $("st-realtime").textContent = on ? "real time" : "as fast as possible";
    $("btn-realtime").classList.toggle("on", this.realtime);
  }

  setFrame(frame) {
    const inLog = frame.log_frame !== null && frame.log_frame !== undefined;
    const t = inLog && this.logT !== null ? this.logT : frame.t;
    $("st-time").textContent = `${t.toFixed(2)} s`;
    $("st-time").dataset.t = t;
    $("st-frame").textContent = inLog ? `log frame ${frame.log_frame}` : `frame ${frame.frame}`;
    this.setRunning(frame.running);
    this.setRealtime(frame.realtime);
    this.dropped = frame.dropped || 0;
    $("st-dropped").textContent = `${this.dropped} dropped`;
  }

  // A log frame's own time (its FrameInfo.time), when the frame message does not carry it.
  setLogTime(t) {
    this.logT = t;
    $("st-time").textContent = `${t.toFixed(2)} s`;
    $("st-time").dataset.t = t;
  }

  // The bridge's status: frames dropped for all pages together.
  setStatus(status) {
    $("st-dropped").title = `frames this page did not get; all pages: ${status.dropped}, pages: ${status.clients}`;
  }
}

// The event banner: falls, lost links and module faults show at once and stay until closed.
export class Banner {
  constructor() {
    $("banner-close").onclick = () => this.hide();
  }

  show(kind, text) {
    const el = $("banner");
    el.dataset.kind = kind;
    $("banner-text").textContent = `${kind}: ${text}`;
    el.hidden = false;
  }

  hide() {
    $("banner").hidden = true;
  }
}
