// Log frames whose frame message carried no samples (a bridge that samples only a running
// simulation): the page reads the watched keys with `get` and files them under the shown frame's
// FrameInfo.time, so plots still fill as a log is played or scrubbed.

const TIME_KEY = "representation:FrameInfo.time";

export class LogSampler {
  constructor(conn, store, onSampled) {
    this.conn = conn;
    this.store = store;
    this.onSampled = onSampled; // (t) after a row is filed
    this.wanted = null; // the log frame still to sample
    this.busy = false;
  }

  onFrame(m) {
    if (m.log_frame === null || m.log_frame === undefined) return;
    if (m.samples && m.samples.rows && m.samples.rows.length) return; // the bridge sampled it
    this.wanted = m.log_frame;
    this.pump();
  }

  // One frame at a time; while one is read, only the latest wanted frame waits.
  async pump() {
    if (this.busy || this.wanted === null) return;
    const k = this.wanted;
    this.wanted = null;
    this.busy = true;
    const keys = this.store.keys();
    const replies = await Promise.all([TIME_KEY, ...keys].map((key) => this.conn.get(key)));
    const t = Number(replies[0].text);
    if (!replies[0].error && Number.isFinite(t)) {
      const row = [t, ...replies.slice(1).map((r) => (r.error ? null : Number(r.text)))];
      if (keys.length) this.store.addFrame({ log_frame: k, samples: { keys, rows: [row] } });
      this.onSampled(t); // the frame's own time, for the plots' cursor and the status line
    }
    this.busy = false;
    this.pump();
  }
}
