// Watched numbers as one table (time column + a column per key), filled from frame.samples.
// Plots and text watches register the keys they need; the bridge is told the union (op watch).

const MAX_ROWS = 200000; // ~33 min at 100 Hz; older rows are dropped
const MAX_KEYS = 64; // the bridge's limit

export class SampleStore {
  constructor(conn) {
    this.conn = conn;
    this.users = new Map(); // key -> Set of owner ids
    this.t = [];
    this.logFrame = []; // the log frame of each row (mode log), else null
    this.cols = new Map(); // key -> values, aligned with t
    this.version = 0; // bumps on every change, so views redraw only when needed
    this.mode = "sim";
    this.onError = () => {};
  }

  keys() {
    return [...this.users.keys()];
  }

  // Registers owner's interest in key; false (and an error) past the bridge's limit.
  add(key, owner) {
    if (!this.users.has(key)) {
      if (this.users.size >= MAX_KEYS) {
        this.onError(`watch: at most ${MAX_KEYS} keys at once`);
        return false;
      }
      this.users.set(key, new Set());
      this.cols.set(key, new Array(this.t.length).fill(null));
      this.sendWatch();
    }
    this.users.get(key).add(owner);
    return true;
  }

  remove(key, owner) {
    const set = this.users.get(key);
    if (!set) return;
    set.delete(owner);
    if (set.size === 0) {
      this.users.delete(key);
      this.cols.delete(key);
      this.sendWatch();
    }
  }

  // The bridge refused a key ("... 'key' ..."): drop it for every owner.
  rejectFrom(errorText) {
    for (const key of this.keys())
      if (errorText.includes(key)) {
        this.users.delete(key);
        this.cols.delete(key);
        this.version++;
        this.sendWatch();
        return key;
      }
    return null;
  }

  sendWatch() {
    this.version++;
    this.conn.send({ op: "watch", keys: this.keys() });
  }

  clear() {
    this.t = [];
    this.logFrame = [];
    for (const k of this.cols.keys()) this.cols.set(k, []);
    this.version++;
  }

  // Appends a frame's rows; a simulation that went back in time (reset) starts over, while a
  // log's rows go in time order wherever they fall (scrubbing).
  addFrame(frame) {
    const s = frame.samples;
    if (!s || !s.rows || s.rows.length === 0) return;
    const inLog = frame.log_frame !== null && frame.log_frame !== undefined;
    for (const row of s.rows) {
      const t = row[0];
      const last = this.t.length ? this.t[this.t.length - 1] : -Infinity;
      if (!inLog && t < last) this.clear();
      let i = this.t.length;
      if (inLog && t <= last) {
        i = this.indexAtOrAfter(t);
        if (this.t[i] !== t) this.insertRow(i, t);
      } else this.insertRow(i, t);
      this.logFrame[i] = inLog ? frame.log_frame : null;
      s.keys.forEach((k, j) => {
        const col = this.cols.get(k);
        if (col) col[i] = row[j + 1];
      });
    }
    if (this.t.length > MAX_ROWS) this.dropFirst(this.t.length - MAX_ROWS);
    this.version++;
  }

  insertRow(i, t) {
    this.t.splice(i, 0, t);
    this.logFrame.splice(i, 0, null);
    for (const col of this.cols.values()) col.splice(i, 0, null);
  }

  dropFirst(n) {
    this.t.splice(0, n);
    this.logFrame.splice(0, n);
    for (const col of this.cols.values()) col.splice(0, n);
  }

  // First row index with time >= t (binary search).
  indexAtOrAfter(t) {
    let lo = 0, hi = this.t.length;
    while (lo < hi) {
      const mid = (lo + hi) >> 1;
      if (this.t[mid] < t) lo = mid + 1;
      else hi = mid;
    }
    return lo;
  }

  latest(key) {
    const col = this.cols.get(key);
    if (!col) return null;
    for (let i = col.length - 1; i >= 0 && i >= col.length - 100; i--) if (col[i] !== null) return col[i];
    return null;
  }

  // Rows [i0, i1) as uPlot data: [t, col(keys[0]), col(keys[1]), ...].
  slice(keys, i0, i1) {
    return [this.t.slice(i0, i1), ...keys.map((k) => (this.cols.get(k) || []).slice(i0, i1))];
  }
}
