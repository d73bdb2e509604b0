// The status line (mode, target, sim time, running, real time, dropped, connection) and the
// run/pause/step/reset/realtime buttons of a local simulation.

const $ = (id) => document.getElementById(id);

export class StatusBar {
  constructor(consolePane) {
    this.consolePane = consolePane;
    this.realtime = false;
    this.dropped = 0;
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
    $("st-time").textContent = `${frame.t.toFixed(2)} s`;
    $("st-time").dataset.t = frame.t;
    const inLog = frame.log_frame !== null && frame.log_frame !== undefined;
    $("st-frame").textContent = inLog ? `log frame ${frame.log_frame}` : `frame ${frame.frame}`;
    this.setRunning(frame.running);
    this.setRealtime(frame.realtime);
    this.dropped = frame.dropped || 0;
    $("st-dropped").textContent = `${this.dropped} dropped`;
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
