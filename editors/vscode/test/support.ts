// Where the tests find the repository and the postproc executable (POSTPROC, else the Release
// build, else the Debug build of the repository).
import * as fs from 'node:fs';
import * as path from 'node:path';

export const repository = path.resolve(__dirname, '../../../..');

export function postproc(): string {
  if (process.env.POSTPROC) return process.env.POSTPROC;
  for (const build of ['build-release', 'build']) {
    const candidate = path.join(repository, build, 'bin', 'postproc');
    if (fs.existsSync(candidate)) return candidate;
  }
  throw new Error('no postproc executable: build the repository or set POSTPROC');
}
