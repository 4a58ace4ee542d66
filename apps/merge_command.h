// `ringid merge`: the shard summaries of one campaign as one (apps/campaign.h).
#ifndef RINGID_APPS_MERGE_COMMAND_H_
#define RINGID_APPS_MERGE_COMMAND_H_

namespace ringid {

int MergeCommand(int argc, char** argv);

}  // namespace ringid

#endif  // RINGID_APPS_MERGE_COMMAND_H_
