// `postproc explain` output, read back: for each NC line, the toolpath command and the GPP line that
// wrote it. The format (docs/engine.md, "explain"):
//   ==> SAMPLE.NC <==
//      9 N70 T3 M6                               | #5 @change_tool -> @change_tool (fanuc.gpp:147)
// The GPP file is the post by its name, or an include file by its path relative to the post's folder.
import * as path from 'path';

export interface ExplainedLine {
  ncFile: string;     // the output file's name ("SAMPLE.NC")
  ncLine: number;     // 1-based
  text: string;       // the NC line
  command: string;    // "#5 @change_tool": the toolpath command
  procedure: string;  // "@change_tool": the GPP procedure that wrote it
  gppFile: string;    // "fanuc.gpp", "lib/moves.inc"
  gppLine: number;    // 1-based
}

const header = /^==> (.+) <==$/;
const origin = /^#(\d+) (\S+) -> (\S+) \((.+):(\d+)\)\s*$/;

export function parseExplain(output: string): ExplainedLine[] {
  const lines: ExplainedLine[] = [];
  let file = '';
  for (const raw of output.split(/\r?\n/)) {
    const h = header.exec(raw);
    if (h) {
      file = h[1];
      continue;
    }
    const bar = raw.lastIndexOf(' | #');
    if (bar < 0) continue;
    const left = raw.slice(0, bar);
    const m = origin.exec(raw.slice(bar + 3));
    const n = /^\s*(\d+) ?(.*)$/.exec(left);
    if (!m || !n) continue;
    lines.push({
      ncFile: file,
      ncLine: Number(n[1]),
      text: n[2].trimEnd(),
      command: `#${m[1]} ${m[2]}`,
      procedure: m[3],
      gppFile: m[4],
      gppLine: Number(m[5]),
    });
  }
  return lines;
}

// Where the GPP file of an explained line is, for the post at `post`.
export function gppPath(post: string, gppFile: string): string {
  return path.resolve(path.dirname(post), gppFile);
}
