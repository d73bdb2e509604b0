// The log player (mode log): play, pause, step, scrub; every move is one `log goto k`, and the
// next waits for the last one's reply so a slow bridge is never flooded.

const $ = (id) => document.getElementById(id);

export class LogPlayer {
  constructor(conn) {
    this.conn = conn;
    this.frames = 0;
    this.shown = 0;
    this.period = 0.01;
    this.playing = false;
    this.inFlight = false;
    this.wanted = null; // the frame to show next, once the bridge is free
    this.scrub = $("log-scrub");
    $("log-play").onclick = () => this.play();
    $("log-pause").onclick = () => this.pause();
    $("log-step").onclick = () => this.goto(this.shown + 1);
    $("log-back").onclick = () => this.goto(this.shown - 1);
    this.scrub.addEventListener("input", () => {
      this.pause();
      this.goto(+this.scrub.value);
    });
  }

  setHello(hello) {
    this.frames = hello.log_frames || 0;
    this.period = hello.period || 0.01;
    this.scrub.max = Math.max(0, this.frames - 1);
    this.label();
  }

  setFrame(frame) {
    if (frame.log_frame === null || frame.log_frame === undefined) return;
    this.shown = frame.log_frame;
    this.scrub.value = this.shown;
    this.label();
  }

  label() {
    $("log-frame").textContent = `${this.shown} / ${Math.max(0, this.frames - 1)}`;
  }

  goto(k) {
    this.wanted = Math.max(0, Math.min(this.frames - 1, Math.round(k)));
    this.pump();
  }

  async pump() {
    if (this.inFlight || this.wanted === null) return;
    const k = this.wanted;
    this.wanted = null;
    this.inFlight = true;
    const reply = await this.conn.cmd(`log goto ${k}`);
    this.inFlight = false;
    if (!reply.ok) this.pause();
    this.pump();
  }

  // Plays at the log's own rate, or as fast as the bridge answers if that is slower.
  play() {
    if (this.playing || this.frames === 0) return;
    this.playing = true;
    $("log-play").classList.add("on");
    let last = performance.now();
    let due = this.shown;
    const step = (now) => {
      if (!this.playing) return;
      due += (now - last) / 1000 / this.period;
      last = now;
      if (due >= this.frames - 1) {
        this.goto(this.frames - 1);
        return this.pause();
      }
      if (!this.inFlight && Math.floor(due) !== this.shown) this.goto(Math.floor(due));
      requestAnimationFrame(step);
    };
    requestAnimationFrame(step);
  }

  pause() {
    this.playing = false;
    $("log-play").classList.remove("on");
  }
}
