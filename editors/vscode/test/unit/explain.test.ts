// The extension's reading of `postproc explain`, on its real output for the shipped Fanuc post.
import { strict as assert } from 'node:assert';
import * as cp from 'node:child_process';
import * as path from 'node:path';
import { test } from 'node:test';
import { gppPath, parseExplain } from '../../src/explain';
import { postproc, repository } from '../support';

test('explain output maps each NC line to its command and GPP line', () => {
  const out = cp.execFileSync(postproc(), [
    'explain', '--post', path.join(repository, 'machines/fanuc/fanuc.gpp'), '--prp',
    path.join(repository, 'machines/fanuc/fanuc.prp'), '-q', path.join(repository, 'docs/examples/sample-job.trace'),
  ]).toString();
  const lines = parseExplain(out);
  assert.ok(lines.length > 50, `${lines.length} lines`);
  const change = lines.find((l) => l.text.endsWith('T3 M6'));
  assert.ok(change);
  assert.equal(change.ncFile, 'SAMPLE.NC');
  assert.equal(change.command, '#5 @change_tool');
  assert.equal(change.procedure, '@change_tool');
  assert.equal(change.gppFile, 'fanuc.gpp');
  assert.ok(change.gppLine > 100);
  assert.deepEqual(lines.map((l) => l.ncLine).slice(0, 3), [1, 2, 3]);
});

test('a line with a bar of its own keeps its text', () => {
  const [line] = parseExplain('==> A.NC <==\n   7 (A | B) | #3 @message -> @message (p.gpp:12)\n');
  assert.deepEqual(line, {
    ncFile: 'A.NC', ncLine: 7, text: '(A | B)', command: '#3 @message', procedure: '@message', gppFile: 'p.gpp', gppLine: 12,
  });
});

test('a line of an include file names it relative to the post, and resolves there', () => {
  const [line] = parseExplain('==> A.NC <==\n   3 G1 | #2 @line -> @line (lib/moves.inc:3)\n');
  assert.equal(line.gppFile, 'lib/moves.inc');
  assert.equal(line.gppLine, 3);
  assert.equal(gppPath('/posts/p.gpp', line.gppFile), path.resolve('/posts/lib/moves.inc'));
  assert.equal(gppPath('/posts/p.gpp', 'p.gpp'), path.resolve('/posts/p.gpp'));
  assert.equal(gppPath('/posts/p.gpp', '/elsewhere/common.inc'), path.resolve('/elsewhere/common.inc'));
});
