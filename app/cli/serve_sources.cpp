#include "app/cli/serve_sources.h"

#include <chrono>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/cli/mcap_output.h"
#include "app/cli/source_options.h"
#include "core/bridge/session_parameters.h"
#include "core/export/mcap_recording_export.h"
#include "core/export/ros_schemas.h"
#include "core/export/ros_tf.h"
#include "core/link/record_tap.h"
#include "core/link/session_io.h"
#include "core/record/recording_metadata.h"

namespace ydscope::cli {
namespace {

using Clock = std::chrono::steady_clock;
using foxglove::Parameter;
using foxglove::SessionParameters;

// /tf_static again this often: a client that subscribes late still learns every pose.
constexpr std::chrono::seconds kTfRepeat{1};

// Channel ids: each source's topics in a block of kRosTopicCount, /tf_static after them (from 1).
std::uint32_t channel_id(std::size_t source, RosTopic topic) {
  return static_cast<std::uint32_t>(source * kRosTopicCount + static_cast<std::size_t>(topic) + 1);
}
std::uint32_t tf_channel_id(std::size_t sources) { return static_cast<std::uint32_t>(sources * kRosTopicCount + 1); }

// Every source's parameters under "NAME/", each forwarded to that source's own.
class SourcesParameters final : public foxglove::ParameterBackend {
 public:
  void add(std::string name, SessionParameters* parameters) { sources_.push_back({std::move(name), parameters}); }
  std::vector<Parameter> current() override {
    std::vector<Parameter> out;
    for (const auto& [name, parameters] : sources_)
      for (Parameter p : parameters->current()) out.push_back({name + "/" + p.name, p.value});
    return out;
  }
  void set(const Parameter& parameter, SetDone done) override {
    const std::size_t slash = parameter.name.find('/');
    for (const auto& [name, parameters] : sources_) {
      if (slash == std::string::npos || parameter.name.compare(0, slash, name) != 0 || slash != name.size()) continue;
      const std::string prefix = name + "/";
      return parameters->set({parameter.name.substr(slash + 1), parameter.value},
                             [prefix, done](std::vector<Parameter> read_back, std::string error) {
                               for (Parameter& p : read_back) p.name = prefix + p.name;
                               done(std::move(read_back), std::move(error));
                             });
    }
    std::string names;
    for (const auto& source : sources_) names += (names.empty() ? "" : ", ") + source.first;
    done({}, "there is no parameter '" + parameter.name + "'; this server's are NAME/scan_hz and the like for " + names);
  }

 private:
  std::vector<std::pair<std::string, SessionParameters*>> sources_;
};

struct Source {
  SourceSpec spec;
  std::unique_ptr<Session> session;
  std::unique_ptr<SessionParameters> parameters;
  std::shared_ptr<RecordTap> tap;
  std::unique_ptr<RosTopicEncoder> encoder;  // without --mcap
  LinkState last_state = LinkState::Idle;
};

std::vector<foxglove::ServerChannel> channels_of(const std::vector<Source>& sources) {
  std::vector<foxglove::ServerChannel> out;
  for (std::size_t id = 0; id < sources.size(); ++id)
    for (const RosTopicInfo& t : ros_topics())
      out.push_back({channel_id(id, t.topic), "/" + sources[id].spec.name + std::string(t.name),
                     std::string(t.schema->name), std::string(t.schema->text)});
  const RosSchema& tf = tf_message_schema();
  out.push_back({tf_channel_id(sources.size()), "/tf_static", std::string(tf.name), std::string(tf.text)});
  return out;
}

}  // namespace

int serve_sources(const Arguments& args, foxglove::ServerOptions server_options, const std::atomic<bool>& stop) {
  const auto seconds = args.number("seconds", 0.001, 1e9);
  const auto mcap_path = args.value("mcap");
  if (mcap_path) refuse_to_overwrite(*mcap_path, args, "--mcap");
  const McapExportOptions export_options = mcap_options_from(args);
  std::vector<Source> sources;
  std::vector<McapSource> mcap_sources;
  SourcesParameters parameters;
  for (SourceSpec& spec : source_specs_from(args, /*scan=*/true)) {
    spec.config.reconnect = true;
    mcap_sources.push_back({spec.name, spec.pose, spec.config.model});
    Source source{std::move(spec), std::make_unique<Session>(4), nullptr, std::make_shared<RecordTap>(), nullptr};
    source.parameters = std::make_unique<SessionParameters>(*source.session);
    sources.push_back(std::move(source));
  }
  for (Source& source : sources) parameters.add(source.spec.name, source.parameters.get());
  server_options.name = "ydscope on " + std::to_string(sources.size()) + " lidars";

  foxglove::FoxgloveServer server(server_options, channels_of(sources), &parameters);
  std::string error;
  if (!server.start(error)) throw std::runtime_error(error);
  const auto publish = [&server](std::uint32_t channel, std::uint64_t log_time, std::span<const std::uint8_t> cdr) {
    server.publish(channel, log_time, std::make_shared<const std::vector<std::uint8_t>>(cdr.begin(), cdr.end()));
  };

  std::unique_ptr<McapRecordingExport> mcap;
  if (mcap_path) {
    mcap = McapRecordingExport::create(*mcap_path, export_options, error, mcap_sources);
    if (!mcap) throw std::runtime_error(error);
    mcap->set_observer([&](std::size_t source, RosTopic topic, std::uint64_t log_time, std::span<const std::uint8_t> cdr) {
      publish(channel_id(source, topic), log_time, cdr);
    });
  } else {
    for (std::size_t id = 0; id < sources.size(); ++id) {
      RosExportOptions ros = export_options.ros;
      ros.frame.frame_id = mcap_sources[id].name;
      ros.model = mcap_sources[id].model;
      sources[id].encoder = std::make_unique<RosTopicEncoder>(std::move(ros));
    }
  }
  std::vector<RosTransform> transforms;
  for (const McapSource& source : mcap_sources)
    transforms.push_back(ros_transform_of(source.pose, export_options.ros.frame, kCommonFrameId, source.name));

  for (Source& source : sources) {
    source.session->connect(source.spec.config);
    source.session->start_tap(source.tap);
  }
  std::printf("serving ws://%s:%u for %zu lidars:", server_options.host.c_str(), static_cast<unsigned>(server.port()),
              sources.size());
  for (const Source& source : sources) std::printf(" %s on %s", source.spec.name.c_str(), source.spec.config.address.c_str());
  std::printf("\n");
  std::fflush(stdout);

  const auto start = Clock::now();
  auto last_flush = Clock::now();
  auto last_tf = Clock::time_point{};
  std::vector<TapRecord> records;
  std::vector<std::uint8_t> tf_cdr;
  Lap lap;
  while (!stop.load() && (!seconds || std::chrono::duration<double>(Clock::now() - start).count() < *seconds)) {
    if (Clock::now() - last_tf >= kTfRepeat) {
      const auto now_ns = static_cast<std::uint64_t>(
          std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch()).count());
      encode_tf_message(transforms, now_ns, tf_cdr);
      publish(tf_channel_id(sources.size()), now_ns, tf_cdr);
      last_tf = Clock::now();
    }
    for (std::size_t id = 0; id < sources.size(); ++id) {
      Source& source = sources[id];
      source.tap->wait_and_take(records, std::chrono::milliseconds(id == 0 ? 20 : 0));
      RosTopicEncoder& topics = mcap ? mcap->encoder(id) : *source.encoder;
      topics.set_filter(source.parameters->filter());
      for (const TapRecord& r : records) {
        if (mcap) {
          mcap->record(r.type, r.payload, r.t_ns, static_cast<std::uint16_t>(id));
        } else {
          topics.record(r.type, r.payload, r.t_ns, [&](RosTopic topic, std::uint64_t log_time, std::span<const std::uint8_t> cdr) {
            publish(channel_id(id, topic), log_time, cdr);
          });
        }
      }
      source.tap->recycle(records);
      source.session->laps().drain_newest(lap);  // the served laps come from the tap
      const SessionSnapshot s = source.session->snapshot();
      if (s.state != source.last_state) {
        source.last_state = s.state;
        const bool bad = s.state == LinkState::Failed || s.state == LinkState::Reconnecting || s.state == LinkState::Stalled;
        server.broadcast_status(bad ? foxglove::StatusLevel::Warning : foxglove::StatusLevel::Info,
                                source.spec.name + ": lidar " + std::string(link_state_name(s.state)) +
                                    (s.message.empty() ? "" : ": " + s.message));
        if (bad) std::fprintf(stderr, "ydscope-cli serve: %s: %s\n", source.spec.name.c_str(), describe_snapshot(s).c_str());
      }
      if (const auto dropped = source.tap->dropped())
        topics.set_extra_diagnostics({{"tap_dropped_records", std::to_string(dropped)}});
    }
    if (mcap && Clock::now() - last_flush >= std::chrono::milliseconds(900)) {
      if (!mcap->flush()) throw std::runtime_error("writing " + *mcap_path + " failed: " + mcap->error());
      last_flush = Clock::now();
    }
  }

  for (Source& source : sources) source.session->stop_tap(source.tap);
  for (const auto& c : server.clients())
    std::fprintf(stderr, "ydscope-cli serve: client %s: %llu messages sent, %llu dropped\n", c.peer.c_str(),
                 static_cast<unsigned long long>(c.sent), static_cast<unsigned long long>(c.dropped));
  server.stop();
  for (Source& source : sources) source.session->disconnect();
  if (mcap) {
    for (std::size_t id = 0; id < sources.size(); ++id)
      while (sources[id].tap->wait_and_take(records, std::chrono::milliseconds(200))) {
        for (const TapRecord& r : records) mcap->record(r.type, r.payload, r.t_ns, static_cast<std::uint16_t>(id));
        sources[id].tap->recycle(records);
      }
    if (!mcap->finish()) throw std::runtime_error("writing " + *mcap_path + " failed: " + mcap->error());
    std::uint64_t laps = 0;
    for (std::size_t id = 0; id < sources.size(); ++id) laps += mcap->encoder(id).laps();
    std::fprintf(stderr, "ydscope-cli serve: wrote %s: %llu laps, %llu messages\n", mcap_path->c_str(),
                 static_cast<unsigned long long>(laps), static_cast<unsigned long long>(mcap->statistics().message_count));
  }
  return 0;
}

}  // namespace ydscope::cli
