// Dynamic resolution for the 3D view: while frames keep coming and the page draws fewer than 30 a
// second (a software GL such as SwiftShader), draw fewer pixels; once the view is still, draw it
// sharp again. In headless Chromium under load, half resolution drew 35 frames/s against 22.

const MIN_FPS = 30;
const RAISE_FPS = 55; // raise again only with room to spare, so the scale does not swing
const STEP = 0.25;
const MIN_SCALE = 0.5;

export class RenderScale {
  constructor(view) {
    this.view = view;
    this.scale = 1;
    this.since = performance.now();
    this.draws = 0;
    this.ticks = 0;
    this.lastDraw = this.since;
  }

  // Called each animation frame with whether the view drew.
  tick(drew, now = performance.now()) {
    this.ticks++;
    if (drew) {
      this.draws++;
      this.lastDraw = now;
    } else if (this.scale < 1 && now - this.lastDraw > 500) {
      this.set(1); // still: one sharp picture
    }
    if (now - this.since < 1000) return;
    const fps = (this.draws * 1000) / (now - this.since);
    const busy = this.draws >= 0.8 * this.ticks; // something new nearly every animation frame
    if (busy && fps < MIN_FPS && this.scale > MIN_SCALE) this.set(this.scale - STEP);
    else if (busy && fps > RAISE_FPS && this.scale < 1) this.set(this.scale + STEP);
    this.since = now;
    this.draws = this.ticks = 0;
  }

  set(scale) {
    this.scale = scale;
    this.view.renderer.setPixelRatio((window.devicePixelRatio || 1) * scale);
    this.view.resize();
  }
}
