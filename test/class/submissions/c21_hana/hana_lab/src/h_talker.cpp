// Hana's talker: each line typed is published on chatter.
#include <iostream>
#include <string>
#include <ros/ros.h>
#include <std_msgs/String.h>

int main(int argc, char** argv) {
  ros::init(argc, argv, "h_talker");
  ros::NodeHandle n;
  ros::Publisher pub = n.advertise<std_msgs::String>("chatter", 10);
  std::string line;
  while (ros::ok() && std::getline(std::cin, line)) {
    std_msgs::String msg;
    msg.data = line;
    pub.publish(msg);
  }
  return 0;
}
