// Console keys: "representation:X.field[2]" -> the settable top ("representation:X") and the
// field path below it ("field[2]"), as `set <top> <field>=<value>` takes them.

export function splitKey(key) {
  const m = /^([a-z_]+:[^.[\]]+)\.?(.*)$/.exec(key);
  return m ? { top: m[1], field: m[2] } : { top: key, field: "" };
}
