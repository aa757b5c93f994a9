// The status line beside the transport bar's time bar: what was saved where, what failed, what
// the hand holds, and words about a moment of the run ("the run is back at t = 0, the theory
// hidden"), which go once the run has left that moment (the trial read "the run is back at
// t = 0" at t = 2.49 s with the theory shown). It says the present state only.
#pragma once

#include <optional>
#include <string>

namespace frictionlab::classroom {

struct StatusLine {
  std::string text;  // what it says; whoever has news writes it here

  // Says `words` about the run's moment: at `frame`, with the theory kept back or not.
  void say_of_moment(std::string words, long frame, bool theory_hidden) {
    text = std::move(words);
    moment_ = Moment{text, frame, theory_hidden};
  }
  // What it says with the run at `frame` and the theory kept back or not: words about a moment
  // only while both still hold; "" for nothing.
  std::string now(long frame, bool theory_hidden) const {
    if (moment_ && moment_->text == text && (moment_->frame != frame || moment_->theory_hidden != theory_hidden)) return "";
    return text;
  }

 private:
  struct Moment {
    std::string text;
    long frame = 0;
    bool theory_hidden = false;
  };
  std::optional<Moment> moment_;
};

}  // namespace frictionlab::classroom
