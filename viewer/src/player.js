// Playback clock: the shot's time, advanced by animation frames at the chosen
// speed while playing; stops at the end of the shot.

export class Player {
  /**
   * @param {number} duration s
   * @param {(t:number, playing:boolean) => void} onChange after every change of time or state
   */
  constructor(duration, onChange) {
    this.duration = Math.max(0, duration);
    this.time = 0;
    this.speed = 1;
    this.playing = false;
    this.onChange = onChange;
    this.lastFrame = null;
    this.frame = this.frame.bind(this);
  }

  play() {
    if (this.playing) return;
    if (this.time >= this.duration) this.time = 0; // replay from the start
    this.playing = true;
    this.lastFrame = null;
    requestAnimationFrame(this.frame);
    this.onChange(this.time, true);
  }

  pause() {
    if (!this.playing) return;
    this.playing = false;
    this.onChange(this.time, false);
  }

  toggle() {
    if (this.playing) this.pause();
    else this.play();
  }

  seek(t) {
    this.time = Math.min(this.duration, Math.max(0, Number(t) || 0));
    this.lastFrame = null;
    this.onChange(this.time, this.playing);
  }

  setSpeed(speed) {
    if (speed > 0) this.speed = speed;
  }

  frame(now) {
    if (!this.playing) return;
    if (this.lastFrame !== null) {
      // at most 0.1 s of wall time per frame, so a stalled tab does not jump
      const wall = Math.min(0.1, (now - this.lastFrame) / 1000);
      this.time = Math.min(this.duration, this.time + wall * this.speed);
    }
    this.lastFrame = now;
    if (this.time >= this.duration) this.playing = false;
    this.onChange(this.time, this.playing);
    if (this.playing) requestAnimationFrame(this.frame);
  }
}
